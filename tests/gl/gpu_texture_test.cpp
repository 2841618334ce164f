// Textures on the GPU (gl/internal/gpu_texture.h) with a real context: an RGBA texture uploaded with
// the CPU's mipmap levels holds, level for level, what the GL's own glGenerateMipmap makes of it
// (llvmpipe: texel for texel), for sizes whose sides halve, end in 1 or pass through 3.
#include "gl/internal/gpu_texture.h"

#include <random>

#include <gtest/gtest.h>

#include "gl/gl_context.h"
#include "gl/internal/gl_api.h"
#include "gl/internal/mip_levels.h"
#include "support/gl_required.h"

namespace urdfsnap::gl {
namespace {

// Every mipmap level of the texture bound to GL_TEXTURE_2D, level 0 first.
std::vector<std::vector<std::uint8_t>> Levels(int width, int height) {
  std::vector<std::vector<std::uint8_t>> levels;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (int level = 0; level < MipLevelCount(width, height); ++level) {
    const int w = std::max(1, width >> level), h = std::max(1, height >> level);
    std::vector<std::uint8_t>& texels = levels.emplace_back(static_cast<size_t>(w) * h * 4);
    glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  return levels;
}

TEST(GpuTextureTest, UploadsTheMipLevelsTheGlGenerates) {
  URDFSNAP_REQUIRE_GL();
  const std::unique_ptr<GlContext> context = CreateGlContext(std::nullopt);
  context->MakeCurrent();
  std::mt19937 random(21);
  for (const auto& [width, height] : {std::pair{64, 64}, {48, 12}, {12, 48}, {6, 2}, {3, 1}, {2, 3}}) {
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    ASSERT_TRUE(MipLevelsExact(width, height));
    texture::TextureImage image{width, height, 4, {}};
    for (int i = 0; i < width * height * 4; ++i) image.texels.push_back(static_cast<std::uint8_t>(random()));
    const GpuTexture uploaded(image);
    uploaded.Bind(0);
    const auto ours = Levels(width, height);
    unsigned generated = 0;
    glGenTextures(1, &generated);
    glBindTexture(GL_TEXTURE_2D, generated);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.texels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    const auto theirs = Levels(width, height);
    glDeleteTextures(1, &generated);
    EXPECT_EQ(ours.front(), image.texels);
    for (size_t level = 0; level < ours.size(); ++level) EXPECT_EQ(ours[level], theirs[level]) << "level " << level;
  }
}

}  // namespace
}  // namespace urdfsnap::gl
