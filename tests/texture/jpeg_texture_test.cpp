// JPEG textures decoded as Ogre's FreeImage codec decodes them for RViz: exact texels against
// FreeImage's own output, and errors for broken and oversized files (unit).
#include "texture/jpeg_texture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "image/png_reader.h"
#include "texture/texture_file.h"

namespace urdfsnap::texture {
namespace {

namespace fs = std::filesystem;

const fs::path kJpegs = fs::path(URDFSNAP_SOURCE_DIR) / "tests/data/jpeg";

std::string Bytes(const fs::path& path) {
  std::ostringstream bytes;
  bytes << std::ifstream(path, std::ios::binary).rdbuf();
  return bytes.str();
}

TEST(JpegTextureTest, TexelsAreFreeImagesDefaultDecoding) {
  // gradients.jpg: 40x24, 4:2:0 chroma; gradients_freeimage.png: FreeImage 3.18's
  // FreeImage_Load(FIF_JPEG, path, 0), as Ogre 1.12's codec calls it. stb_image decodes 1,011 of
  // the 2,880 values more than 5 levels brighter and 885 more than 5 darker.
  const std::shared_ptr<const TextureImage> texture = LoadTextureFile((kJpegs / "gradients.jpg").string());
  const image::Image expected = image::ReadPng((kJpegs / "gradients_freeimage.png").string());
  ASSERT_EQ(texture->width, expected.width);
  ASSERT_EQ(texture->height, expected.height);
  ASSERT_EQ(texture->channels, 4);
  int differing = 0;
  for (size_t i = 0; i < static_cast<size_t>(expected.width) * expected.height; ++i) {
    for (int c = 0; c < 3; ++c) differing += texture->texels[4 * i + c] != expected.rgb[3 * i + c];
    EXPECT_EQ(texture->texels[4 * i + 3], 255);
  }
  EXPECT_EQ(differing, 0);
}

TEST(JpegTextureTest, OnlyJpegFilesAreTakenForJpeg) {
  const std::string jpeg = Bytes(kJpegs / "gradients.jpg");
  EXPECT_TRUE(IsJpeg(jpeg));
  EXPECT_FALSE(IsJpeg(Bytes(kJpegs / "gradients_freeimage.png")));
  EXPECT_FALSE(IsJpeg(""));
  EXPECT_FALSE(IsJpeg("\xFF\xD8"));
}

void ExpectError(const std::string& bytes, const std::string& reason) {
  try {
    DecodeJpegAsFreeImage(bytes, "broken.jpg");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("broken.jpg: cannot read texture: ", 0), 0u) << what;
    EXPECT_NE(what.find(reason), std::string::npos) << what;
  }
}

TEST(JpegTextureTest, BrokenAndOversizedFilesAreErrors) {
  const std::string jpeg = Bytes(kJpegs / "gradients.jpg");
  // cut inside the headers: libjpeg's own reason
  ExpectError(jpeg.substr(0, 40), "JPEG datastream contains no image");
  // the frame header's height and width (SOF0: FF C0, length, precision, then 16-bit sizes) set
  // to 20000 x 20000
  std::string huge = jpeg;
  const size_t sof = huge.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  huge[sof + 5] = huge[sof + 7] = static_cast<char>(20000 >> 8);
  huge[sof + 6] = huge[sof + 8] = static_cast<char>(20000 & 0xFF);
  ExpectError(huge, "20000x20000 pixels is larger than 16384 on a side");
}

}  // namespace
}  // namespace urdfsnap::texture
