// demos/texture_compression/texture_compression_gl.hpp — the compressed texture through GL:
// uploaded as the blocks texture_compression_math.hpp encoded, its size asked back, and
// GL's own decode read back to compare with the CPU's.
//   glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, w, h, 0, bytes, blocks)
//   glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size)
//   glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)    (GL decodes)
#pragma once
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/gl/gl.hpp"

namespace dxt {
struct GlResult {
  bool supported = false;   // GL_EXT_texture_compression_s3tc
  bool compressed = false;  // GL_TEXTURE_COMPRESSED after the upload
  long bytes = 0;           // GL_TEXTURE_COMPRESSED_IMAGE_SIZE
  ts::Image decoded;        // what GL reads from it, row 0 = the first row uploaded
};

inline GlResult glRoundTrip(const std::vector<uint8_t>& blocks, int w, int h) {
  GlResult out;
  out.supported = ts::gl::hasExtension("GL_EXT_texture_compression_s3tc");
  if (!out.supported) return out;
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, w, h, 0, GLsizei(blocks.size()),
                         blocks.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  GLint compressed = 0, size = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  out.compressed = compressed != 0, out.bytes = size;
  out.decoded = ts::Image(w, h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.decoded.pixels.data());
  glDeleteTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, GLuint(previous));
  ts::gl::check("the DXT1 round trip");
  return out;
}
}  // namespace dxt
