// Reading points out of a PointCloud2's bytes, checked first: the cloud's claims (width x height
// points of point_step bytes, rows row_step apart, a field at its offset) are held against the
// bytes present before anything is read or allocated, so a cloud that lies is an error naming what
// does not fit and never a read out of bounds. Values of any PointField datatype come out as
// floats, in either byte order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "display/point_cloud_message.h"

namespace urdfsnap::display {

// A cloud that cannot be read; what() says which claim does not hold.
class CloudError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PointCloudReader {
 public:
  // Checks the layout (not the fields: those are checked by Field). Throws CloudError when the
  // data is shorter than height rows of row_step bytes (the last needing only width * point_step),
  // or when rows overlap (row_step < width * point_step with more than one row). RViz ignores
  // row_step; a one-row cloud is read without it here too.
  explicit PointCloudReader(const PointCloud2& cloud);
  PointCloudReader(PointCloud2&&) = delete;   // the cloud is kept by reference

  std::size_t size() const { return count_; }

  // The index of the field `name`, or -1.
  int Find(std::string_view name) const;
  // The index of the field `name` checked for reading (see Check). Throws CloudError when there is
  // no such field.
  int Field(std::string_view name) const;
  // Checks field `field` for reading: a known datatype whose first element lies inside point_step.
  // Throws CloudError naming the field otherwise.
  void Check(int field) const;
  std::uint8_t Datatype(int field) const { return cloud_.fields[field].datatype; }

  // Field `field` (as Field returned it) of point `i` (row-major), converted to float.
  float Value(int field, std::size_t i) const;
  // The 32 bits of a 4-byte field of point `i`, in the machine's byte order (RGB8's packed colour).
  std::uint32_t Bits(int field, std::size_t i) const;

 private:
  const std::uint8_t* At(int field, std::size_t i) const;
  const PointCloud2& cloud_;
  std::size_t count_ = 0;
  bool swap_ = false;
};

// The bytes of one element of a PointField datatype (1..8); 0 for an unknown one.
std::size_t DatatypeSize(std::uint8_t datatype);

}  // namespace urdfsnap::display
