// The environment maps as textures (env_maps.hpp).
#include "common/core/env_maps.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/kept.hpp"
#include "common/core/parallel.hpp"

namespace ts::envmaps {
namespace {
// The maps made so far, by what makes them: a figure's passes ask for the
// same map many times (the dynamic cube map's background, in every face of
// every pass it measures), and each costs a world colour per texel (made
// on both cores).
struct MapInputs {
  Param p;
  int face;
  glm::dmat3 view;
  bool operator==(const MapInputs& o) const { return p == o.p && face == o.face && view == o.view; }
};
Kept<MapInputs, std::shared_ptr<const Image>> g_maps(8);

std::shared_ptr<const Image> mapPicture(Param p, int face, const glm::dmat3& sphereView) {
  return g_maps.get({p, face, sphereView}, [&] {
    const Size sz = mapSize(p, face);
    const int faces = p == kCube ? 6 : 1;
    const glm::dmat3 toWorld = glm::transpose(sphereView);
    auto img = std::make_shared<Image>(sz.w, sz.h * faces);
    evenAndOdd(faces * sz.h, [&](int y) {  // row j is t = (j + 1/2) / h (a cube face's rows f h + j)
      const int f = y / sz.h, j = y % sz.h;
      for (int i = 0; i < sz.w; ++i)
        img->set(i, y, toRgba(worldColour(texelDir(p, f, (i + 0.5) / sz.w, (j + 0.5) / sz.h, toWorld))));
    });
    return std::shared_ptr<const Image>(img);
  });
}
}  // namespace

TextureDesc environmentMap(Param p, int face, const glm::dmat3& sphereView) {
  std::shared_ptr<const Image> img = mapPicture(p, face, sphereView);
  TextureDesc t;
  t.name = "environment_map";
  t.params = {{"param", kParamKeys[p]}, {"face", std::to_string(face)}};
  if (p == kSphere) {  // the eye the sphere map is made for: its rotation's columns, world -> eye
    std::string v;
    char b[32];
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) {
        std::snprintf(b, sizeof b, "%.9g", sphereView[c][k]);
        v += (v.empty() ? "" : " ") + std::string(b);
      }
    t.params.push_back({"sphere_view", v});
  }
  t.image = img;
  t.cube = p == kCube;
  t.minFilter = t.magFilter = GL_LINEAR;
  t.wrapS = p == kLatLong ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

TextureDesc unwrappedMap(Param p, int face, const glm::dmat3& sphereView) {
  TextureDesc t = environmentMap(p, face, sphereView);
  t.params.push_back({"layout", "unwrapped"});
  const Size sz = mapSize(p, face), all = unwrappedSize(p, face);
  Image img(all.w, all.h);  // row 0 at the top while it is laid out
  for (int f = 0; f < (p == kCube ? 6 : 1); ++f)
    for (int j = 0; j < sz.h; ++j)
      for (int i = 0; i < sz.w; ++i) {
        Rgba c = t.image->at(i, f * sz.h + j);
        const double u = 2 * (i + 0.5) / sz.w - 1, v = 2 * (j + 0.5) / sz.h - 1;
        const double up = 4 * (i + 0.5) / sz.w - (i < sz.w / 2 ? 1 : 3);  // across the paraboloid's disc
        if ((p == kSphere && u * u + v * v > 1) || (p == kParaboloid && up * up + v * v > 1)) c = toRgba(kBackground);
        if (p == kCube) img.set((f % 3) * sz.w + i, (f / 3) * sz.h + j, c);  // t down
        else img.set(i, sz.h - 1 - j, c);                                    // t up
      }
  img.flipVertical();  // a texture's row 0 is v = 0, the bottom
  t.image = std::make_shared<const Image>(std::move(img));
  t.cube = false;
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

TextureDesc environmentMapFromParams(const std::vector<std::pair<std::string, std::string>>& params) {
  auto get = [&](const char* key) -> const std::string* {
    for (const auto& [k, v] : params)
      if (k == key) return &v;
    return nullptr;
  };
  const std::string* param = get("param");
  const std::string* face = get("face");
  if (!param || !face) throw Error("environment_map: needs params 'param' and 'face'");
  int p = -1;
  for (int k = 0; k < kParams; ++k)
    if (*param == kParamKeys[k]) p = k;
  if (p < 0) throw Error("environment_map: unknown param '" + *param + "' (latlong, cube, sphere, paraboloid)");
  char* end = nullptr;
  const long n = std::strtol(face->c_str(), &end, 10);
  if (face->empty() || *end || n < 1 || n > 1024) throw Error("environment_map: face '" + *face + "' is not 1..1024");
  glm::dmat3 view(1.0);
  if (p == kSphere) {
    const std::string* v = get("sphere_view");
    if (!v) throw Error("environment_map: a sphere map needs 'sphere_view' (nine numbers)");
    std::istringstream in(*v);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        if (!(in >> view[c][k])) throw Error("environment_map: sphere_view '" + *v + "' is not nine numbers");
    std::string rest;
    if (in >> rest) throw Error("environment_map: sphere_view '" + *v + "' is not nine numbers");
  }
  const std::string* layout = get("layout");
  if (layout && *layout != "unwrapped") throw Error("environment_map: unknown layout '" + *layout + "' (unwrapped)");
  TextureDesc t = layout ? unwrappedMap(Param(p), int(n), view) : environmentMap(Param(p), int(n), view);
  t.params = params;  // the recorded key, as written
  return t;
}
}  // namespace ts::envmaps
