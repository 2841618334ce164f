// The zlib streams of the PNG writers (png_writer.cpp's 8-bit images, gray16_png.cpp's 16-bit
// ones): libdeflate at level 2, one compressor per thread. Internal to the image library.
#pragma once

struct libdeflate_compressor;

namespace urdfsnap::image {

// The calling thread's compressor, made on its first use (its tables, ~0.5 MB, are reused, not
// rebuilt per image); null when out of memory.
libdeflate_compressor* ThreadZlibCompressor();

}  // namespace urdfsnap::image
