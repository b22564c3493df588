#include "sidecar_reader.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/core/error.hpp"
#include "common/core/sidecar.hpp"
#include "common/core/texture_generators.hpp"
#include "common/core/textures.hpp"

namespace ref {
namespace {
// The sidecar read with nlohmann-json; the key order is kept (ordered_json),
// so "state" comes back in the order the demo lists its options.
using Json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw ts::Error("sidecar: " + where + ": " + what);
}
// A texture no generator remakes (an unknown name, not bad params): the one
// failure SidecarReadOptions::unknownPictures turns into a placeholder.
struct UnknownGenerator : ts::Error {
  using ts::Error::Error;
};

// Member lookup: nullptr if absent (or `v` is not an object).
const Json* find(const Json& v, const std::string& key) {
  if (!v.is_object()) return nullptr;
  auto it = v.find(key);
  return it == v.end() ? nullptr : &*it;
}
const Json& member(const Json& v, const std::string& key, const std::string& where) {
  if (!v.is_object()) fail(where, std::string("expected an object, found ") + v.type_name());
  const Json* m = find(v, key);
  if (!m) fail(where, "missing key '" + key + "'");
  return *m;
}
const Json& array(const Json& v, const std::string& where) {
  if (!v.is_array()) fail(where, std::string("expected an array, found ") + v.type_name());
  return v;
}
const Json& object(const Json& v, const std::string& where) {
  if (!v.is_object()) fail(where, std::string("expected an object, found ") + v.type_name());
  return v;
}
// A number; null reads as NaN (the writer writes non-finite floats as null).
double number(const Json& v, const std::string& where) {
  if (v.is_null()) return std::nan("");
  if (!v.is_number()) fail(where, std::string("expected a number, found ") + v.type_name());
  return v.get<double>();
}
int integer(const Json& v, const std::string& where, double lo, double hi) {
  double x = number(v, where);
  if (!(x >= lo && x <= hi))
    fail(where, "expected a number in " + std::to_string(int(lo)) + ".." + std::to_string(int(hi)));
  return int(x);
}
std::string text(const Json& v, const std::string& where) {
  if (!v.is_string()) fail(where, std::string("expected a string, found ") + v.type_name());
  return v.get<std::string>();
}
bool boolean(const Json& v, const std::string& where) {
  if (!v.is_boolean()) fail(where, std::string("expected true/false, found ") + v.type_name());
  return v.get<bool>();
}
template <int N>
glm::vec<N, float> vec(const Json& v, const std::string& where) {
  if (!v.is_array() || v.size() != size_t(N)) fail(where, "expected an array of " + std::to_string(N) + " numbers");
  glm::vec<N, float> out;
  for (int i = 0; i < N; ++i) out[i] = float(number(v[size_t(i)], where));
  return out;
}
glm::mat4 mat(const Json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 16) fail(where, "expected 16 numbers (column-major)");
  glm::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = float(number(v[size_t(c * 4 + r)], where));
  return m;
}

using ts::strParam;

// glTexGen's environment-mapping modes: the mode, no planes.
// False if `mode` is not one of them.  Sphere mapping makes s and t only.
bool readNormalTexGen(const Json& tg, const std::string& mode, const std::string& tw, ts::TexGen* out) {
  if (mode == "GL_SPHERE_MAP") out->mode = GL_SPHERE_MAP;
  else if (mode == "GL_REFLECTION_MAP") out->mode = GL_REFLECTION_MAP;
  else if (mode == "GL_NORMAL_MAP") out->mode = GL_NORMAL_MAP;
  else return false;
  if (find(tg, "planes") || find(tg, "plane_modelview")) fail(tw, mode + " takes no planes");
  return true;
}

ts::Prim primFromName(const std::string& s, const std::string& where) {
  if (s == "triangles") return ts::Prim::Triangles;
  if (s == "lines") return ts::Prim::Lines;
  if (s == "line_strip") return ts::Prim::LineStrip;
  if (s == "line_loop") return ts::Prim::LineLoop;
  if (s == "points") return ts::Prim::Points;
  fail(where, "unknown primitive '" + s + "'");
}
}  // namespace

GLenum glEnumFromName(const std::string& name) {
  static const std::pair<const char*, GLenum> k[] = {
      {"GL_NEAREST", GL_NEAREST},
      {"GL_LINEAR", GL_LINEAR},
      {"GL_NEAREST_MIPMAP_NEAREST", GL_NEAREST_MIPMAP_NEAREST},
      {"GL_LINEAR_MIPMAP_NEAREST", GL_LINEAR_MIPMAP_NEAREST},
      {"GL_NEAREST_MIPMAP_LINEAR", GL_NEAREST_MIPMAP_LINEAR},
      {"GL_LINEAR_MIPMAP_LINEAR", GL_LINEAR_MIPMAP_LINEAR},
      {"GL_REPEAT", GL_REPEAT},
      {"GL_MIRRORED_REPEAT", GL_MIRRORED_REPEAT},
      {"GL_CLAMP_TO_EDGE", GL_CLAMP_TO_EDGE},
      {"GL_CLAMP_TO_BORDER", GL_CLAMP_TO_BORDER},
      {"GL_CLAMP", GL_CLAMP},
      {"GL_REPLACE", GL_REPLACE},
      {"GL_MODULATE", GL_MODULATE},
      {"GL_DECAL", GL_DECAL},
      {"GL_BLEND", GL_BLEND},
      {"GL_ADD", GL_ADD},
      {"GL_FASTEST", GL_FASTEST},
      {"GL_NICEST", GL_NICEST},
      {"GL_DONT_CARE", GL_DONT_CARE},
      // alpha functions and blend factors
      {"GL_NEVER", GL_NEVER},
      {"GL_LESS", GL_LESS},
      {"GL_EQUAL", GL_EQUAL},
      {"GL_LEQUAL", GL_LEQUAL},
      {"GL_GREATER", GL_GREATER},
      {"GL_NOTEQUAL", GL_NOTEQUAL},
      {"GL_GEQUAL", GL_GEQUAL},
      {"GL_ALWAYS", GL_ALWAYS},
      {"GL_ZERO", GL_ZERO},
      {"GL_ONE", GL_ONE},
      {"GL_SRC_COLOR", GL_SRC_COLOR},
      {"GL_ONE_MINUS_SRC_COLOR", GL_ONE_MINUS_SRC_COLOR},
      {"GL_DST_COLOR", GL_DST_COLOR},
      {"GL_ONE_MINUS_DST_COLOR", GL_ONE_MINUS_DST_COLOR},
      {"GL_SRC_ALPHA", GL_SRC_ALPHA},
      {"GL_ONE_MINUS_SRC_ALPHA", GL_ONE_MINUS_SRC_ALPHA},
      // unit 1's GL_COMBINE
      {"GL_TEXTURE", GL_TEXTURE},
      {"GL_COMBINE", GL_COMBINE},
      {"GL_ADD_SIGNED", GL_ADD_SIGNED},
      {"GL_INTERPOLATE", GL_INTERPOLATE},
      {"GL_CONSTANT", GL_CONSTANT},
      {"GL_PRIMARY_COLOR", GL_PRIMARY_COLOR},
      {"GL_PREVIOUS", GL_PREVIOUS},
      {"GL_SUBTRACT", GL_SUBTRACT},
      {"GL_MODULATE_ADD_ATI", GL_MODULATE_ADD_ATI},
  };
  for (const auto& [n, e] : k)
    if (name == n) return e;
  if (name.size() > 2 && name[0] == '0' && (name[1] == 'x' || name[1] == 'X')) {
    char* end = nullptr;
    unsigned long v = std::strtoul(name.c_str() + 2, &end, 16);
    if (*end == 0) return GLenum(v);
  }
  throw ts::Error("sidecar: unknown GL enum '" + name + "'");
}

ts::TextureDesc remakeTexture(const std::string& name, const std::vector<std::pair<std::string, std::string>>& p,
                              const std::string& baseDir) {
  // Every generator is asked in turn (common/core/texture_generators.hpp): the
  // core's own and those the demos register from their folders.
  ts::TextureDesc made;
  if (ts::remakeRegisteredTexture(name, p, &made)) return made;
  if (name == "file") {
    std::string path = strParam(p, "path", name);
    if (!baseDir.empty() && !path.empty() && path[0] != '/') path = baseDir + "/" + path;
    ts::TextureDesc t = ts::fileTexture(path);
    t.params = p;  // keep the recorded key
    return t;
  }
  throw UnknownGenerator("sidecar: unknown texture generator '" + name + "' (known: " + ts::textureGeneratorLabels() +
                         ", file)");
}

constexpr int kMaxNesting = 4;  // frames inside frames: a texture's rendered_from, at most this deep
static void readFrame(const Json& doc, const std::string& baseDir, int nesting, const SidecarReadOptions& ro,
                      SidecarScene& out);

static SidecarScene read(const std::string& jsonText, const std::string& baseDir, const SidecarReadOptions& ro) {
  Json doc;
  try {
    doc = Json::parse(jsonText);
  } catch (const Json::exception& e) {
    throw ts::Error(std::string("json: ") + e.what());
  }
  if (!doc.is_object()) fail("document", "expected an object");
  SidecarScene out;
  auto optText = [&](const char* key, std::string* dst) {
    if (const Json* v = find(doc, key)) *dst = text(*v, key);
  };
  optText("figure", &out.figure);
  optText("book_number", &out.bookNumber);
  optText("caption", &out.caption);
  optText("demo", &out.demo);
  optText("command", &out.command);
  if (const Json* st = find(doc, "state"))
    for (const auto& [k, v] : object(*st, "state").items()) out.state.emplace_back(k, text(v, "state." + k));

  readFrame(doc, baseDir, 0, ro, out);
  return out;
}

// The frame's keys of a sidecar object (the document, or a texture's
// "rendered_from": a nested frame) into out.frame; `nesting`
// counts the frames around it (at most kMaxNesting).
static void readFrame(const Json& doc, const std::string& baseDir, int nesting, const SidecarReadOptions& ro,
                      SidecarScene& out) {
  ts::Frame& f = out.frame;
  const Json& size = member(doc, "size", "document");
  if (!size.is_array() || size.size() != 2) fail("size", "expected [width, height]");
  f.width = integer(size[0], "size", 1, ts::kMaxImageDimension);
  f.height = integer(size[1], "size", 1, ts::kMaxImageDimension);
  if (const Json* c = find(doc, "clear_color")) f.clearColor = vec<4>(*c, "clear_color");
  if (const Json* h = find(doc, "perspective_correction_hint")) {
    try {
      f.perspectiveHint = glEnumFromName(text(*h, "perspective_correction_hint"));
    } catch (const ts::Error& e) {
      fail("perspective_correction_hint", e.what());
    }
  }

  if (const Json* r = find(doc, "renderer")) out.renderer = text(*r, "renderer");
  // The state every panel is drawn with: the reference models exactly this,
  // so a file that says otherwise is refused rather than misread.
  if (const Json* fs = find(doc, "fixed_state")) {
    auto expect = [&](const char* key, const std::string& want) {
      std::string got = text(member(*fs, key, "fixed_state"), std::string("fixed_state.") + key);
      if (got != want) fail(std::string("fixed_state.") + key, "'" + got + "', the reference models " + want + " only");
    };
    const Json& bf = member(*fs, "blend_func", "fixed_state");
    std::string blend;
    for (size_t k = 0; k < array(bf, "fixed_state.blend_func").size(); ++k)
      blend += (k ? " " : "") + text(bf[k], "fixed_state.blend_func");
    if (blend != "GL_SRC_ALPHA GL_ONE_MINUS_SRC_ALPHA GL_ZERO GL_ONE")
      fail("fixed_state.blend_func",
           "'" + blend + "', the reference models GL_SRC_ALPHA GL_ONE_MINUS_SRC_ALPHA GL_ZERO GL_ONE only");
    expect("depth_func", "GL_LESS");
    expect("shade_model", "GL_SMOOTH");
    if (boolean(member(*fs, "cull_face", "fixed_state"), "fixed_state.cull_face") ||
        boolean(member(*fs, "lighting", "fixed_state"), "fixed_state.lighting"))
      fail("fixed_state", "face culling and lighting are not modelled by the reference");
    out.fixedStateKnown = true;
  } else {
    out.missing.push_back("fixed_state");
  }

  const Json& textures = member(doc, "textures", "document");
  for (size_t i = 0; i < array(textures, "textures").size(); ++i) {
    const Json& t = textures[i];
    std::string where = "textures[" + std::to_string(i) + "]";
    std::string name = text(member(t, "name", where), where + ".name");
    std::vector<std::pair<std::string, std::string>> params;
    if (const Json* pv = find(t, "params"))
      for (const auto& [k, v] : object(*pv, where + ".params").items())
        params.emplace_back(k, text(v, where + ".params." + k));
    ts::TextureDesc d;
    bool placeholder = false;  // a picture no generator remakes (SidecarReadOptions::unknownPictures)
    // A picture no generator remakes, when the options allow one here (the
    // top frame's): a grey placeholder of the recorded size (faces or slices
    // stacked), listed so that its pixels are exempt.  Else the read fails.
    const auto unknownPicture = [&](const std::string& at, const std::string& why) {
      if (!(ro.unknownPictures && nesting == 0)) throw UnknownGenerator("sidecar: " + at + ": " + why);
      const int w = integer(member(t, "width", where), where + ".width", 1, ts::kMaxImageDimension);
      int h = integer(member(t, "height", where), where + ".height", 1, ts::kMaxImageDimension);
      if (const Json* c = find(t, "cube"); c && boolean(*c, where + ".cube")) h *= 6;
      if (const Json* dp = find(t, "depth")) h *= integer(*dp, where + ".depth", 1, ts::kMaxImageDimension);
      if (h > ts::kMaxImageDimension) fail(where, "the picture's recorded size is out of range");
      d = ts::TextureDesc{};
      d.name = name, d.params = params;
      d.image = std::make_shared<ts::Image>(w, h, ts::Rgba{128, 128, 128, 255});
      out.unknownPictures.push_back(int(i));
      placeholder = true;
    };
    if (const Json* rf = find(t, "rendered_from")) {
      // A nested frame: the texture is that frame's picture,
      // which the reference recomputes; no generator, no image here.  A
      // nested frame that shows an unknown picture is itself one.
      if (nesting >= kMaxNesting)
        fail(where + ".rendered_from", "frames nested deeper than " + std::to_string(kMaxNesting));
      SidecarScene inner;
      std::string unknown;  // the nested frame shows a texture no generator remakes
      const auto withoutPrefix = [](std::string what) {
        return what.rfind("sidecar: ", 0) == 0 ? what.substr(9) : what;
      };
      try {
        readFrame(object(*rf, where + ".rendered_from"), baseDir, nesting + 1, SidecarReadOptions{}, inner);
      } catch (const UnknownGenerator& e) {
        unknown = withoutPrefix(e.what());
      } catch (const ts::Error& e) {
        fail(where + ".rendered_from", withoutPrefix(e.what()));
      }
      if (!unknown.empty()) {
        unknownPicture(where + ".rendered_from", unknown);
      } else {
        d.name = name, d.params = params;
        const ts::Frame& nf = inner.frame;
        if (const Json* w = find(t, "width"))
          if (integer(*w, where + ".width", 0, ts::kMaxImageDimension) != nf.width)
            fail(where, "width differs from its frame's");
        // A cube map's "height" is a face's: its frame holds the six faces stacked.
        const Json* c = find(t, "cube");
        const int faces = c && boolean(*c, where + ".cube") ? 6 : 1;
        if (const Json* h = find(t, "height"))
          if (integer(*h, where + ".height", 0, ts::kMaxImageDimension) * faces != nf.height)
            fail(where, "height differs from its frame's");
        d.renderedFrom = std::make_shared<const ts::Frame>(nf);
      }
    } else {
      try {
        d = remakeTexture(name, params, baseDir);
      } catch (const UnknownGenerator& e) {
        unknownPicture(where, e.what());
      } catch (const ts::Error& e) {
        fail(where, e.what());
      }
    }
    if (const Json* w = find(t, "width"))
      if (d.image && integer(*w, where + ".width", 0, ts::kMaxImageDimension) != d.image->width)
        fail(where, "the remade texture's width differs");
    // A cube map: the generator's image holds the six faces
    // stacked, and "height" is a face's.
    if (const Json* c = find(t, "cube")) d.cube = boolean(*c, where + ".cube");
    if (d.cube && d.renderedFrom && d.renderedFrom->height != 6 * d.renderedFrom->width)
      fail(where, "a cube map rendered from a frame needs a frame of six stacked square faces");
    if (d.cube && !d.renderedFrom && (!d.image || d.image->height != 6 * d.image->width))
      fail(where, "a cube map needs an image of six stacked square faces");
    // A 3D texture: the generator's image holds the `depth` slices stacked,
    // and "height" is a slice's.
    if (const Json* dp = find(t, "depth")) {
      d.depth = integer(*dp, where + ".depth", 1, ts::kMaxImageDimension);
      if (d.cube && d.depth > 1) fail(where, "a texture is a cube map or 3D, not both");
      if (!d.image || d.image->height % d.depth != 0)
        fail(where, "a 3D texture needs an image of depth stacked slices");
      try {
        d.wrapR = glEnumFromName(text(member(t, "wrap_r", where), where + ".wrap_r"));
      } catch (const ts::Error& e) {
        fail(where, e.what());
      }
    }
    if (const Json* h = find(t, "height"))
      if (d.image &&
          integer(*h, where + ".height", 0, ts::kMaxImageDimension) * (d.cube ? 6 : d.depth) != d.image->height)
        fail(where, "the remade texture's height differs");
    const Json& mips = member(t, "mipmaps", where);
    if (mips.is_boolean()) {
      if (mips.get<bool>()) fail(where, "mipmaps: true is not a kind of chain");
      d.mipmaps = false;
      d.mipLevels = nullptr;
    } else {
      std::string kind = text(mips, where + ".mipmaps");
      d.mipmaps = true;
      if (kind == "explicit") {
        if (!d.mipLevels && !placeholder) fail(where, "explicit mip levels, but generator '" + name + "' makes none");
        if (placeholder) d.mipLevels = nullptr;  // the 2x2 chain of the grey placeholder: its pixels are exempt anyway
      } else if (kind == "box_2x2" || kind == "box_linear_light") {
        d.mipLevels = nullptr;
        d.linearLightMips = kind == "box_linear_light";
      } else {
        fail(where, "unknown mip chain '" + kind + "'");
      }
    }
    try {
      d.minFilter = glEnumFromName(text(member(t, "min_filter", where), where));
      d.magFilter = glEnumFromName(text(member(t, "mag_filter", where), where));
      d.wrapS = glEnumFromName(text(member(t, "wrap_s", where), where));
      d.wrapT = glEnumFromName(text(member(t, "wrap_t", where), where));
    } catch (const ts::Error& e) {
      fail(where, e.what());
    }
    if (const Json* b = find(t, "border")) d.border = vec<4>(*b, where + ".border");
    if (const Json* a = find(t, "max_anisotropy")) d.maxAnisotropy = float(number(*a, where));
    if (const Json* b = find(t, "lod_bias")) d.lodBias = float(number(*b, where));
    f.textures.push_back(std::move(d));
  }

  if (const Json* progs = find(doc, "programs"))
    for (size_t i = 0; i < array(*progs, "programs").size(); ++i) {
      const Json& p = (*progs)[i];
      std::string where = "programs[" + std::to_string(i) + "]";
      ts::Program prog;
      if (const Json* s = find(p, "source")) prog.file = text(*s, where);
      f.programs.emplace_back(text(member(p, "name", where), where), prog);
    }

  const Json& panels = member(doc, "panels", "document");
  for (size_t pi = 0; pi < array(panels, "panels").size(); ++pi) {
    const Json& pv = panels[pi];
    std::string where = "panels[" + std::to_string(pi) + "]";
    ts::Panel p;
    if (const Json* id = find(pv, "id")) p.id = text(*id, where + ".id");
    const Json& vpv = member(pv, "viewport", where);
    if (!vpv.is_array() || vpv.size() != 4) fail(where + ".viewport", "expected [x, y, width, height]");
    auto coord = [&](int i, double lo) {  // x, y may lie off the target; w, h at most the largest image
      return integer(vpv[size_t(i)], where + ".viewport", lo, ts::kMaxImageDimension);
    };
    p.viewport = {coord(0, -ts::kMaxImageDimension), coord(1, -ts::kMaxImageDimension), coord(2, 0), coord(3, 0)};
    if (const Json* d = find(pv, "depth_test")) p.depthTest = boolean(*d, where + ".depth_test");
    if (const Json* c = find(pv, "clear")) p.clear = boolean(*c, where + ".clear");
    else out.missing.push_back(where + ".clear");
    if (const Json* c = find(pv, "clear_color")) p.clearColor = vec<4>(*c, where + ".clear_color");
    p.projection = mat(member(pv, "projection", where), where + ".projection");
    p.modelview = mat(member(pv, "modelview", where), where + ".modelview");
    const Json& batches = member(pv, "batches", where);
    for (size_t bi = 0; bi < array(batches, where + ".batches").size(); ++bi) {
      const Json& bv = batches[bi];
      std::string bw = where + ".batches[" + std::to_string(bi) + "]";
      ts::Batch b;
      if (const Json* r = find(bv, "role")) b.role = text(*r, bw + ".role");
      b.prim = primFromName(text(member(bv, "primitive", bw), bw + ".primitive"), bw);
      b.texture = integer(member(bv, "texture", bw), bw + ".texture", -1, double(f.textures.size()) - 1);
      try {
        b.texEnv = glEnumFromName(text(member(bv, "tex_env", bw), bw + ".tex_env"));
      } catch (const ts::Error& e) {
        fail(bw, e.what());
      }
      if (const Json* pr = find(bv, "program")) b.program = text(*pr, bw + ".program");
      if (const Json* us = find(bv, "uniforms"))
        for (const auto& [k, v] : object(*us, bw + ".uniforms").items())
          b.uniforms.push_back({k, vec<4>(v, bw + ".uniforms." + k)});
      if (const Json* lw = find(bv, "line_width")) b.lineWidth = float(number(*lw, bw));
      if (const Json* ps = find(bv, "point_size")) b.pointSize = float(number(*ps, bw));
      else if (b.prim == ts::Prim::Points) out.missing.push_back(bw + ".point_size");
      if (const Json* bl = find(bv, "blend")) b.blend = boolean(*bl, bw + ".blend");
      // Optional (absent = GL's defaults): GL_TEXTURE_ENV_COLOR, the texture
      // matrix, GL_COLOR_SUM with each vertex's secondary colour.
      if (const Json* ec = find(bv, "tex_env_color")) b.envColor = vec<4>(*ec, bw + ".tex_env_color");
      if (const Json* tm = find(bv, "texture_matrix")) b.textureMatrix = mat(*tm, bw + ".texture_matrix");
      if (const Json* cs = find(bv, "color_sum")) b.colorSum = boolean(*cs, bw + ".color_sum");
      if (const Json* tg = find(bv, "tex_gen")) {  // glTexGen: mode, coordinates, planes (and eye planes' modelview)
        const std::string tw = bw + ".tex_gen", mode = text(member(*tg, "mode", tw), tw + ".mode");
        if (mode == "GL_OBJECT_LINEAR") b.texGen.mode = GL_OBJECT_LINEAR;
        else if (mode == "GL_EYE_LINEAR") b.texGen.mode = GL_EYE_LINEAR;
        else if (readNormalTexGen(*tg, mode, tw, &b.texGen)) {
        }  // GL_SPHERE_MAP, GL_REFLECTION_MAP, GL_NORMAL_MAP
        else
          fail(tw + ".mode", "unknown texgen mode '" + mode + "'");
        const Json& coords = member(*tg, "coords", tw);
        const bool fromNormal = b.texGen.mode != GL_OBJECT_LINEAR && b.texGen.mode != GL_EYE_LINEAR;
        const Json& planes = fromNormal ? Json::object() : member(*tg, "planes", tw);
        const std::string names = "strq";
        for (size_t ci = 0; ci < array(coords, tw + ".coords").size(); ++ci) {
          const std::string c = text(coords[ci], tw + ".coords");
          const size_t k = names.find(c);
          if (c.size() != 1 || k == std::string::npos) fail(tw + ".coords", "unknown coordinate '" + c + "'");
          b.texGen.coords |= 1u << k;
          if (fromNormal) {
            if (k > (b.texGen.mode == GL_SPHERE_MAP ? 1u : 2u))
              fail(tw + ".coords", mode + " does not make '" + c + "' (GL_SPHERE_MAP: s, t; the others: s, t, r)");
            continue;
          }
          b.texGen.planes[k] = vec<4>(member(planes, c, tw + ".planes"), tw + ".planes." + c);
        }
        if (const Json* pm = find(*tg, "plane_modelview")) b.texGen.planeModelview = mat(*pm, tw + ".plane_modelview");
        else if (b.texGen.mode == GL_EYE_LINEAR) fail(tw, "GL_EYE_LINEAR needs plane_modelview");
      }
      if (const Json* cp = find(bv, "clip_plane")) {
        b.clip = true;
        b.clipPlane = vec<4>(*cp, bw + ".clip_plane");
        const Json* cm = find(bv, "clip_plane_modelview");
        if (!cm) fail(bw, "clip_plane needs clip_plane_modelview (the modelview it was given under)");
        b.clipModelview = mat(*cm, bw + ".clip_plane_modelview");
      }
      // Absent = off / FixedState's: the alpha test, the blend's colour factors.
      if (const Json* at = find(bv, "alpha_test")) {
        try {
          b.alphaFunc = glEnumFromName(text(member(*at, "func", bw + ".alpha_test"), bw + ".alpha_test.func"));
        } catch (const ts::Error& e) {
          fail(bw + ".alpha_test.func", e.what());
        }
        b.alphaRef = float(number(member(*at, "ref", bw + ".alpha_test"), bw + ".alpha_test.ref"));
      }
      if (const Json* dw = find(bv, "depth_write")) b.depthWrite = boolean(*dw, bw + ".depth_write");
      if (const Json* df = find(bv, "depth_func")) {  // a second pass's GL_LEQUAL
        try {
          b.depthFunc = glEnumFromName(text(*df, bw + ".depth_func"));
        } catch (const ts::Error& e) {
          fail(bw + ".depth_func", e.what());
        }
        if (b.depthFunc != GL_LESS && b.depthFunc != GL_LEQUAL)
          fail(bw + ".depth_func", "must be GL_LESS or GL_LEQUAL");
      }
      if (const Json* bf = find(bv, "blend_func")) {
        if (array(*bf, bw + ".blend_func").size() != 2) fail(bw + ".blend_func", "needs [source, destination]");
        try {
          b.blendSrc = glEnumFromName(text((*bf)[0], bw + ".blend_func"));
          b.blendDst = glEnumFromName(text((*bf)[1], bw + ".blend_func"));
        } catch (const ts::Error& e) {
          fail(bw + ".blend_func", e.what());
        }
      }
      if (const Json* u1 = find(bv, "unit1")) {  // the second texture unit
        const std::string uw = bw + ".unit1";
        b.texture1 = integer(member(*u1, "texture", uw), uw + ".texture", 0, double(f.textures.size()) - 1);
        if (const Json* tm = find(*u1, "texture_matrix")) b.textureMatrix1 = mat(*tm, uw + ".texture_matrix");
        if (const Json* co = find(*u1, "coords")) {
          const std::string c = text(*co, uw + ".coords");
          if (c != "own") fail(uw + ".coords", "must be \"own\" (each vertex's tex1), not '" + c + "'");
          b.coords1 = true;
        }
        try {
          b.texEnv1 = glEnumFromName(text(member(*u1, "tex_env", uw), uw + ".tex_env"));
          if (b.texEnv1 == GL_COMBINE) {
            b.combine1.rgb = glEnumFromName(text(member(*u1, "combine_rgb", uw), uw + ".combine_rgb"));
            const Json& src = member(*u1, "sources", uw);
            const Json& op = member(*u1, "operands", uw);
            if (array(src, uw + ".sources").size() != 3 || array(op, uw + ".operands").size() != 3)
              fail(uw, "sources and operands need 3 entries each");
            for (size_t k = 0; k < 3; ++k) {
              b.combine1.source[k] = glEnumFromName(text(src[k], uw + ".sources"));
              b.combine1.operand[k] = glEnumFromName(text(op[k], uw + ".operands"));
            }
          }
        } catch (const ts::Error& e) {
          fail(uw, e.what());
        }
      }
      const Json& verts = member(bv, "vertices", bw);
      for (size_t vi = 0; vi < array(verts, bw + ".vertices").size(); ++vi) {
        const Json& vv = verts[vi];
        std::string vw = bw + ".vertices[" + std::to_string(vi) + "]";
        ts::Vertex x;
        x.pos = vec<3>(member(vv, "pos", vw), vw + ".pos");
        if (const Json* t = find(vv, "tex")) x.tex = vec<4>(*t, vw + ".tex");
        if (const Json* c = find(vv, "color")) x.color = vec<4>(*c, vw + ".color");
        if (const Json* c = find(vv, "secondary")) x.secondary = vec<3>(*c, vw + ".secondary");
        if (const Json* t1 = find(vv, "tex1")) x.tex1 = vec<4>(*t1, vw + ".tex1");
        else if (b.coords1) fail(vw, "unit 1 reads its own coordinates: each vertex needs \"tex1\"");
        if (const Json* n = find(vv, "normal")) x.normal = vec<3>(*n, vw + ".normal");
        else if (b.texGen.needsNormal())
          fail(vw, "texgen " + ts::glEnumName(b.texGen.mode) + " needs each vertex's normal");
        b.vertices.push_back(x);
      }
      p.batches.push_back(std::move(b));
    }
    f.panels.push_back(std::move(p));
  }

  if (const Json* labels = find(doc, "labels"))
    for (size_t i = 0; i < array(*labels, "labels").size(); ++i) {
      const Json& lv = (*labels)[i];
      std::string where = "labels[" + std::to_string(i) + "]";
      ts::Label l;
      l.x = float(number(member(lv, "x", where), where + ".x"));
      l.y = float(number(member(lv, "y", where), where + ".y"));
      l.text = text(member(lv, "text", where), where + ".text");
      if (const Json* s = find(lv, "scale")) l.scale = integer(*s, where + ".scale", 1, 64);
      else out.labelGeometryKnown = false, out.missing.push_back(where + ".scale");
      if (const Json* a = find(lv, "align")) {
        std::string al = text(*a, where + ".align");
        if (al == "left") l.align = ts::Align::Left;
        else if (al == "center" || al == "centre") l.align = ts::Align::Center;
        else if (al == "right") l.align = ts::Align::Right;
        else fail(where, "unknown align '" + al + "'");
      } else {
        out.labelGeometryKnown = false;
        out.missing.push_back(where + ".align");
      }
      if (const Json* c = find(lv, "color")) l.color = vec<4>(*c, where + ".color");
      if (const Json* b = find(lv, "background")) l.background = vec<4>(*b, where + ".background");
      f.labels.push_back(std::move(l));
    }
}

SidecarScene readSidecar(const std::string& jsonText, const SidecarReadOptions& options) {
  return read(jsonText, "", options);
}

SidecarScene readSidecarFile(const std::string& path, const std::string& baseDir, const SidecarReadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ts::Error(path + ": cannot open");
  std::ostringstream s;
  s << in.rdbuf();
  try {
    return read(s.str(), baseDir, options);
  } catch (const ts::Error& e) {
    throw ts::Error(path + ": " + e.what());
  }
}
}  // namespace ref
