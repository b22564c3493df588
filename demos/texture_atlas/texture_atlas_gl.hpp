// demos/texture_atlas/texture_atlas_gl.hpp — the atlas demo's own GL passes, in fixed-function GL as seed 001
// teaches them, each recorded (gl::Recording) so that the calls are counted from the calls made and the figures'
// listings show them:
//   - a scene of N objects, each with its own texture (N binds, N glBegin) or all from the atlas (1 and 1);
//   - one tile of a larger picture uploaded in place: glPixelStorei(GL_UNPACK_ROW_LENGTH / _SKIP_PIXELS /
//     _SKIP_ROWS) then glTexSubImage2D from the picture's own memory, read back with glGetTexImage.
// Every pass restores the state it changes (glPushAttrib; the pixel-store values it sets back to what they were)
// and deletes its textures.
#pragma once
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/gl/gl.hpp"
#include "common/gl/gl_record.hpp"
#include "common/gl/pixel_pass.hpp"
#include "common/gl/render.hpp"
#include "demos/texture_atlas/texture_atlas_textures.hpp"

namespace ts::atlas {
// Object k's square: kTile x kTile pixels at its place in a kGrid x kGrid grid, (s, t) from (s0, t0) to (s1, t1).
inline void objectQuad(int k, float s0, float t0, float s1, float t1) {
  const float x = float((k % kGrid) * kTile), y = float((k / kGrid) * kTile);
  glTexCoord2f(s0, t0), glVertex2f(x, y);
  glTexCoord2f(s1, t0), glVertex2f(x + kTile, y);
  glTexCoord2f(s1, t1), glVertex2f(x + kTile, y + kTile);
  glTexCoord2f(s0, t1), glVertex2f(x, y + kTile);
}
inline int countCalls(const std::vector<gl::Call>& calls, size_t from, const char* name) {
  int n = 0;
  for (size_t i = from; i < calls.size(); ++i) n += std::strcmp(calls[i].name, name) == 0;
  return n;
}

// ---- N objects, N textures or one atlas --------------------------------------------------------------------
struct ObjectsRun {
  Image picture;  // the kGrid x kGrid objects, one pixel a texel (GL_NEAREST)
  int binds = 0;  // glBindTexture calls while drawing (the textures' creation not counted)
  int draws = 0;  // glBegin calls while drawing
  gl::CallList calls;
};
// kTiles squares, each showing its own tile: with `atlas` all from the atlas of gutter 0 in one glBegin, else each
// from its own texture, bound before its own glBegin.
inline ObjectsRun objectsPass(Renderer& r, bool atlas) {
  ObjectsRun run;
  r.release();
  gl::Recording rec;
  std::vector<GLuint> textures;
  if (atlas) textures.push_back(imageTexture(atlasImage(0)));
  else
    for (int k = 0; k < kTiles; ++k) textures.push_back(imageTexture(tileImage(k)));
  const size_t drawing = rec.calls().size();
  const int side = kGrid * kTile;
  run.picture = pixelPass(r, side, side, "the objects", [&] {
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    if (atlas) {
      const float n = float(atlasSize(0));
      glBindTexture(GL_TEXTURE_2D, textures[0]);
      glBegin(GL_QUADS);
      for (int k = 0; k < kTiles; ++k)
        objectQuad(k, float(tileX(k, 0)) / n, float(tileY(k, 0)) / n, float(tileX(k, 0) + kTile) / n,
                   float(tileY(k, 0) + kTile) / n);
      glEnd();
    } else {
      for (int k = 0; k < kTiles; ++k) {
        glBindTexture(GL_TEXTURE_2D, textures[size_t(k)]);
        glBegin(GL_QUADS);
        objectQuad(k, 0, 0, 1, 1);
        glEnd();
      }
    }
  });
  run.binds = countCalls(rec.calls(), drawing, "glBindTexture");
  run.draws = countCalls(rec.calls(), drawing, "glBegin");
  glDeleteTextures(GLsizei(textures.size()), textures.data());
  run.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  return run;
}

// The pixel-store values the passes below change, as they were (the renderer's uploads rely on them).
struct PixelStore {
  GLint unpackAlignment = 4, packAlignment = 4;
  PixelStore() {
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
  }
  void restore() const {
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
  }
};

// ---- one tile of a larger picture, uploaded in place ---------------------------------------------------------
struct SubImageRun {
  Image texels;  // the texture's level 0 as glGetTexImage returns it (row 0 = t = 0)
  gl::CallList calls;
};
// A kTile x kTile texture made with no data, then filled from `source` (rowLength x whatever, RGBA8) by one
// glTexSubImage2D that reads the kTile x kTile pixels from (skipPixels, skipRows) on, rows rowLength pixels apart.
inline SubImageRun subImagePass(Renderer& r, const Image& source, int rowLength, int skipPixels, int skipRows) {
  SubImageRun run;
  r.release();
  const PixelStore saved;
  gl::Recording rec;
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kTile, kTile, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kTile, kTile, GL_RGBA, GL_UNSIGNED_BYTE, source.pixels.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  run.texels = Image(kTile, kTile);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, run.texels.pixels.data());
  glDeleteTextures(1, &t);
  saved.restore();
  run.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  return run;
}
// The same tile copied out on the CPU first and uploaded whole (glTexImage2D of the copy), read back.
inline SubImageRun copiedTilePass(Renderer& r, const Image& tile) {
  SubImageRun run;
  r.release();
  const PixelStore saved;
  gl::Recording rec;
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, tile.width, tile.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, tile.pixels.data());
  run.texels = Image(tile.width, tile.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, run.texels.pixels.data());
  glDeleteTextures(1, &t);
  saved.restore();
  run.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  return run;
}
}  // namespace ts::atlas
