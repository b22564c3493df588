#include "common/core/sidecar.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "common/core/text.hpp"

namespace ts {
namespace {
// Written with nlohmann-json (ordered: keys stay in the order below).
using Json = nlohmann::ordered_json;

// A float as the shortest decimal that reads back as the same float (9
// significant digits), whole numbers without a fraction, non-finite as null.
Json num(double v) {
  if (!std::isfinite(v)) return nullptr;
  if (v == std::floor(v) && std::abs(v) < 1e15) return Json(static_cast<long long>(v));  // no "-0", no "1.0"
  // The double nearest the 9-digit decimal ("%.9g" read back by strtod):
  // to_chars with a precision rounds as printf does and from_chars reads as
  // strtod does (both correctly), four times faster than the two, which were
  // a tenth of make_figures for the demos with meshes in their sidecars.
  char buf[40];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf - 1, v, std::chars_format::general, 9);
  double d = 0;
  if (r.ec == std::errc() && std::from_chars(buf, r.ptr, d).ec == std::errc()) return Json(d);
  std::snprintf(buf, sizeof buf, "%.9g", v);  // out of range (a 9-digit rounding past DBL_MAX): as before
  return Json(std::strtod(buf, nullptr));
}
template <int N>
Json vec(const glm::vec<N, float>& v) {
  Json a = Json::array();
  for (int i = 0; i < N; ++i) a.push_back(num(v[i]));
  return a;
}
Json mat(const glm::mat4& m) {  // column-major, as glLoadMatrixf takes it
  Json a = Json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a.push_back(num(m[c][r]));
  return a;
}
const char* primName(Prim p) {
  switch (p) {
    case Prim::Triangles: return "triangles";
    case Prim::Lines: return "lines";
    case Prim::LineStrip: return "line_strip";
    case Prim::LineLoop: return "line_loop";
    case Prim::Points: return "points";
  }
  return "?";
}

// The layout: one line per top-level key, and one per element of the long
// lists (textures, panels, batches, vertices, labels); everything else on
// one line, so a student can read the file and diff two of them.
bool listPerLine(const std::string& key) {
  return key == "textures" || key == "panels" || key == "batches" || key == "vertices" || key == "labels" ||
         key == "inspect" || key == "texels";
}
bool hasListPerLine(const Json& v) {
  if (v.is_object())
    for (const auto& [k, x] : v.items())
      if ((listPerLine(k) && x.is_array() && !x.empty()) || hasListPerLine(x)) return true;
  return false;
}
// The text of one file, appended to `out`: scalars by nlohmann's own
// serializer writing straight into `out` (Json::dump() makes a string and a
// shared adapter for every number, which was most of a mesh's sidecar time),
// keys of plain printable ASCII quoted as dump() quotes them (nothing to
// escape).  The bytes are dump()'s.
class Writer {
 public:
  // `streamed`: the batches whose vertex lists the tree holds as a marker
  // (vertexMarker), written from the batch itself.
  Writer(std::string& out, const std::vector<const Batch*>& streamed)
      : out_(out), streamed_(streamed), scalars_(nlohmann::detail::output_adapter<char, std::string>(out), ' ') {}
  void key(const std::string& k) {
    const bool plain = std::all_of(k.begin(), k.end(),
                                   [](char c) { return c >= 0x20 && c < 0x7f && c != '"' && c != '\\'; });
    if (plain) out_ += '"', out_ += k, out_ += "\": ";
    else out_ += Json(k).dump() + ": ";
  }
  void emit(const Json& v, const std::string& indent) {
    if (v.is_object()) {
      bool multi = hasListPerLine(v);
      out_ += '{';
      bool first = true;
      for (const auto& [k, x] : v.items()) {
        if (!first) out_ += multi && (listPerLine(k) && x.is_array() && !x.empty()) ? ",\n" + indent + " " : ", ";
        first = false;
        key(k);
        if (listPerLine(k) && x.is_array() && !x.empty()) {
          out_ += '[';
          std::string inner = indent + "  ";
          if (k == "vertices" && x.size() == 1 && x[0].is_binary()) {
            vertices(*streamed_.at(size_t(x[0].get_binary().subtype())), inner);
          } else {
            for (size_t i = 0; i < x.size(); ++i) {
              out_ += (i ? ",\n" : "\n") + inner;
              emit(x[i], inner);
            }
          }
          out_ += ']';
        } else {
          emit(x, indent);
        }
      }
      out_ += '}';
    } else if (v.is_array()) {
      out_ += '[';
      for (size_t i = 0; i < v.size(); ++i) {
        if (i) out_ += v[i].is_primitive() ? "," : ", ";
        emit(v[i], indent);
      }
      out_ += ']';
    } else {
      scalars_.dump(v, false, false, 0);  // as v.dump()
    }
  }

 private:
  // A batch's vertices, one a line, as emit() writes the list of objects
  // frameInto once built for them: {"pos": [...], "tex": [...], "color":
  // [...]} and the keys the batch needs.  A mesh has some hundred thousand:
  // a tree of them cost more than all the rest of the file.
  void vertices(const Batch& b, const std::string& inner) {
    for (size_t i = 0; i < b.vertices.size(); ++i) {
      const Vertex& x = b.vertices[i];
      out_ += (i ? ",\n" : "\n") + inner;
      out_ += '{';
      member("pos", x.pos, true);
      member("tex", x.tex);
      member("color", x.color);
      if (b.colorSum) member("secondary", x.secondary);
      if (b.texGen.needsNormal()) member("normal", x.normal);
      if (b.texture1 >= 0 && b.coords1) member("tex1", x.tex1);
      out_ += '}';
    }
  }
  template <int N>
  void member(const char* name, const glm::vec<N, float>& v, bool first = false) {
    if (!first) out_ += ", ";
    key(name);
    out_ += '[';
    for (int i = 0; i < N; ++i) {
      if (i) out_ += ',';
      scalars_.dump(num(v[i]), false, false, 0);
    }
    out_ += ']';
  }

  std::string& out_;
  const std::vector<const Batch*>& streamed_;
  nlohmann::detail::serializer<Json> scalars_;
};
// What frameInto puts where a batch's vertex list goes: a list of one binary
// value whose subtype is the batch's index in `streamed` (Writer writes the
// vertices); an empty batch keeps its empty list.
Json vertexMarker(const Batch& b, std::vector<const Batch*>& streamed) {
  if (b.vertices.empty()) return Json::array();
  Json marker = Json::array();
  marker.push_back(Json::binary({}, std::uint64_t(streamed.size())));
  streamed.push_back(&b);
  return marker;
}

// The environment-mapping texgen modes: the mode and the
// coordinates it generates; no planes (they read the normal).
Json normalTexGenJson(const TexGen& g) {
  Json coords = Json::array();
  const char* names[4] = {"s", "t", "r", "q"};
  for (int k = 0; k < 4; ++k)
    if (g.coords & (1u << k)) coords.push_back(names[k]);
  return {{"mode", glEnumName(g.mode)}, {"coords", coords}};
}
}  // namespace

std::string glEnumName(GLenum e) {
  switch (e) {
    case GL_NEAREST: return "GL_NEAREST";
    case GL_LINEAR: return "GL_LINEAR";
    case GL_NEAREST_MIPMAP_NEAREST: return "GL_NEAREST_MIPMAP_NEAREST";
    case GL_LINEAR_MIPMAP_NEAREST: return "GL_LINEAR_MIPMAP_NEAREST";
    case GL_NEAREST_MIPMAP_LINEAR: return "GL_NEAREST_MIPMAP_LINEAR";
    case GL_LINEAR_MIPMAP_LINEAR: return "GL_LINEAR_MIPMAP_LINEAR";
    case GL_REPEAT: return "GL_REPEAT";
    case GL_MIRRORED_REPEAT: return "GL_MIRRORED_REPEAT";
    case GL_CLAMP_TO_EDGE: return "GL_CLAMP_TO_EDGE";
    case GL_CLAMP_TO_BORDER: return "GL_CLAMP_TO_BORDER";
    case GL_CLAMP: return "GL_CLAMP";
    case GL_ADD: return "GL_ADD";
    case GL_REPLACE: return "GL_REPLACE";
    case GL_MODULATE: return "GL_MODULATE";
    case GL_DECAL: return "GL_DECAL";
    case GL_BLEND: return "GL_BLEND";
    case GL_ZERO: return "GL_ZERO";
    case GL_ONE: return "GL_ONE";
    case GL_SRC_ALPHA: return "GL_SRC_ALPHA";
    case GL_ONE_MINUS_SRC_ALPHA: return "GL_ONE_MINUS_SRC_ALPHA";
    case GL_LESS: return "GL_LESS";
    case GL_SMOOTH: return "GL_SMOOTH";
    case GL_NEVER: return "GL_NEVER";
    case GL_EQUAL: return "GL_EQUAL";
    case GL_LEQUAL: return "GL_LEQUAL";
    case GL_GREATER: return "GL_GREATER";
    case GL_NOTEQUAL: return "GL_NOTEQUAL";
    case GL_GEQUAL: return "GL_GEQUAL";
    case GL_ALWAYS: return "GL_ALWAYS";
    case GL_SRC_COLOR: return "GL_SRC_COLOR";
    case GL_ONE_MINUS_SRC_COLOR: return "GL_ONE_MINUS_SRC_COLOR";
    case GL_DST_COLOR: return "GL_DST_COLOR";
    case GL_ONE_MINUS_DST_COLOR: return "GL_ONE_MINUS_DST_COLOR";
    case GL_TEXTURE: return "GL_TEXTURE";
    case GL_COMBINE: return "GL_COMBINE";
    case GL_ADD_SIGNED: return "GL_ADD_SIGNED";
    case GL_INTERPOLATE: return "GL_INTERPOLATE";
    case GL_CONSTANT: return "GL_CONSTANT";
    case GL_PRIMARY_COLOR: return "GL_PRIMARY_COLOR";
    case GL_PREVIOUS: return "GL_PREVIOUS";
    case GL_SUBTRACT: return "GL_SUBTRACT";
    case GL_MODULATE_ADD_ATI: return "GL_MODULATE_ADD_ATI";
    case GL_SPHERE_MAP: return "GL_SPHERE_MAP";
    case GL_REFLECTION_MAP: return "GL_REFLECTION_MAP";
    case GL_NORMAL_MAP: return "GL_NORMAL_MAP";
    default: {
      char b[16];
      std::snprintf(b, sizeof b, "0x%04X", e);
      return b;
    }
  }
}

// The frame's own keys, in the sidecar's order (the fixed state after the
// size at the top level; a nested frame, TextureDesc::renderedFrom, shares
// the top level's fixed state and writes none).
static void frameInto(Json& d, const Frame& f, bool withFixedState, std::vector<const Batch*>& streamed) {
  d["size"] = {f.width, f.height};
  if (withFixedState)
    d["fixed_state"] = {{"blend_func",
                         {glEnumName(FixedState::blendSrc), glEnumName(FixedState::blendDst),
                          glEnumName(FixedState::blendSrcAlpha), glEnumName(FixedState::blendDstAlpha)}},
                        {"depth_func", glEnumName(FixedState::depthFunc)},
                        {"shade_model", glEnumName(FixedState::shadeModel)},
                        {"cull_face", FixedState::cullFace},
                        {"lighting", FixedState::lighting}};
  d["clear_color"] = vec(f.clearColor);
  d["perspective_correction_hint"] = f.perspectiveHint == GL_FASTEST  ? "GL_FASTEST"
                                     : f.perspectiveHint == GL_NICEST ? "GL_NICEST"
                                                                      : "GL_DONT_CARE";
  Json textures = Json::array();
  for (const TextureDesc& t : f.textures) {
    Json params = Json::object();
    for (const auto& [k, v] : t.params) params[k] = v;
    Json mips = t.mipmaps ? Json(t.mipLevels         ? "explicit"
                                 : t.linearLightMips ? "box_linear_light"
                                                     : "box_2x2")
                          : Json(false);
    textures.push_back({{"name", t.name},
                        {"params", params},
                        {"width", t.image ? t.image->width : 0},
                        {"height", t.image ? t.image->height : 0},
                        {"mipmaps", mips},
                        {"min_filter", glEnumName(t.minFilter)},
                        {"mag_filter", glEnumName(t.magFilter)},
                        {"wrap_s", glEnumName(t.wrapS)},
                        {"wrap_t", glEnumName(t.wrapT)},
                        {"border", vec(t.border)},
                        {"max_anisotropy", num(t.maxAnisotropy)},
                        {"lod_bias", num(t.lodBias)}});
    if (t.depth > 1) {  // a 3D texture: only then, so other sidecars read as before
      textures.back()["depth"] = t.depth;
      textures.back()["height"] = t.image ? t.image->height / t.depth : 0;
      textures.back()["wrap_r"] = glEnumName(t.wrapR);
    }
    if (t.renderedFrom) {  // a nested frame: the frame this texture is the render of
      Json nested;
      frameInto(nested, *t.renderedFrom, false, streamed);
      textures.back()["rendered_from"] = std::move(nested);
    }
    if (t.cube) {  // a cube map: only then; height is a face's
      textures.back()["cube"] = true;
      textures.back()["height"] = t.image ? t.image->height / 6 : 0;
    }
  }
  d["textures"] = std::move(textures);
  Json programs = Json::array();
  for (const auto& [name, prog] : f.programs) programs.push_back({{"name", name}, {"source", prog.file}});
  d["programs"] = programs;
  Json panels = Json::array();
  for (const Panel& p : f.panels) {
    Json batches = Json::array();
    for (const Batch& b : p.batches) {
      Json uniforms = Json::object();
      for (const Uniform& u : b.uniforms) uniforms[u.name] = vec(u.value);
      // Each vertex: pos, tex, color, and only where they matter secondary
      // (the colour sum), normal (texgen reads it), tex1 (unit 1's own
      // coordinates); written by Writer::vertices.
      Json vertices = vertexMarker(b, streamed);
      Json bj = {{"role", b.role},
                 {"primitive", primName(b.prim)},
                 {"texture", b.texture},
                 {"tex_env", glEnumName(b.texEnv)},
                 {"program", b.program},
                 {"uniforms", uniforms},
                 {"line_width", num(b.lineWidth)},
                 {"point_size", num(b.pointSize)},
                 {"blend", b.blend}};
      // Written only when they matter, so sidecars of batches without them
      // read exactly as before: the environment colour (GL_BLEND reads it),
      // the texture matrix (not the identity), the colour sum.
      if (b.texEnv == GL_BLEND || b.envColor != glm::vec4(0.0f)) bj["tex_env_color"] = vec(b.envColor);
      if (b.textureMatrix != glm::mat4(1.0f)) bj["texture_matrix"] = mat(b.textureMatrix);
      if (b.colorSum) bj["color_sum"] = true;
      if (b.texGen.needsNormal()) {
        bj["tex_gen"] = normalTexGenJson(b.texGen);
      } else if (b.texGen.on()) {
        // glTexGen: the mode, the coordinates it generates, their planes and
        // (EYE_LINEAR) the modelview in force when the planes were given.
        Json coords = Json::array(), planes = Json::object();
        const char* names[4] = {"s", "t", "r", "q"};
        for (int k = 0; k < 4; ++k)
          if (b.texGen.coords & (1u << k)) {
            coords.push_back(names[k]);
            planes[names[k]] = vec(b.texGen.planes[k]);
          }
        Json tg = {{"mode", b.texGen.mode == GL_EYE_LINEAR ? "GL_EYE_LINEAR" : "GL_OBJECT_LINEAR"},
                   {"coords", coords},
                   {"planes", planes}};
        if (b.texGen.mode == GL_EYE_LINEAR) tg["plane_modelview"] = mat(b.texGen.planeModelview);
        bj["tex_gen"] = tg;
      }
      if (b.clip) bj["clip_plane"] = vec(b.clipPlane), bj["clip_plane_modelview"] = mat(b.clipModelview);
      // Written only when set (absent reads as off): the alpha test, the blend's colour factors.
      if (b.alphaTest()) bj["alpha_test"] = {{"func", glEnumName(b.alphaFunc)}, {"ref", num(b.alphaRef)}};
      if (b.blendFactors()) bj["blend_func"] = {glEnumName(b.blendSrc), glEnumName(b.blendDst)};
      if (b.depthFunc) bj["depth_func"] = glEnumName(b.depthFunc);
      if (!b.depthWrite) bj["depth_write"] = false;
      if (b.texture1 >= 0) {  // unit 1: its texture, environment and (GL_COMBINE) function
        Json u = {{"texture", b.texture1}, {"tex_env", glEnumName(b.texEnv1)}};
        if (b.texEnv1 == GL_COMBINE) {
          Json src = Json::array(), op = Json::array();
          for (int k = 0; k < 3; ++k)
            src.push_back(glEnumName(b.combine1.source[k])), op.push_back(glEnumName(b.combine1.operand[k]));
          u["combine_rgb"] = glEnumName(b.combine1.rgb);
          u["sources"] = src;
          u["operands"] = op;
        }
        if (b.textureMatrix1 != glm::mat4(1.0f)) u["texture_matrix"] = mat(b.textureMatrix1);
        if (b.coords1) u["coords"] = "own";  // each vertex's "tex1"
        bj["unit1"] = u;
      }
      bj["vertices"] = std::move(vertices);
      batches.push_back(std::move(bj));
    }
    panels.push_back({{"id", p.id},
                      {"viewport", {p.viewport.x, p.viewport.y, p.viewport.w, p.viewport.h}},
                      {"depth_test", p.depthTest},
                      {"clear", p.clear},
                      {"clear_color", vec(p.clearColor)},
                      {"projection", mat(p.projection)},
                      {"modelview", mat(p.modelview)},
                      {"batches", std::move(batches)}});
  }
  d["panels"] = std::move(panels);
  Json labels = Json::array();
  for (const Label& l : f.labels) {
    Json j = {{"x", num(l.x)},
              {"y", num(l.y)},
              {"text", l.text},
              {"scale", l.scale},
              // The height its capitals are drawn at: what a proofreader
              // checks against print size (tests/proofread).
              {"capital_px", text::capitalHeight(l.scale)},
              {"align", l.align == Align::Left     ? "left"
                        : l.align == Align::Center ? "center"
                                                   : "right"},
              {"color", vec(l.color)},
              {"background", vec(l.background)}};
    // Where its numbers come from (written only when it prints any).
    for (const Label::Printed& p : l.printed)
      j["printed"].push_back({{"measurement", p.name}, {"format", p.format}, {"text", p.text}});
    for (const auto& [name, value] : l.given) j["given"].push_back({{"name", name}, {"value", num(value)}});
    labels.push_back(std::move(j));
  }
  d["labels"] = std::move(labels);
  if (!f.legend.empty()) {
    Json legend = Json::array();
    for (const LegendEntry& e : f.legend) legend.push_back({{"color", vec(e.color)}, {"meaning", e.meaning}});
    d["legend"] = std::move(legend);
  }
}

std::string sidecarJson(const Frame& f, const SidecarInfo& info) {
  Json d;
  d["figure"] = info.figureId;
  d["book_number"] = info.bookNumber;
  d["caption"] = info.caption;
  d["demo"] = info.demo;
  d["command"] = info.command;
  d["state"] = Json::object();
  for (const auto& [k, v] : info.state) d["state"][k] = v;
  d["measurements"] = Json::object();
  for (const Measurement& m : info.measurements) d["measurements"][m.name] = num(m.value);
  if (!info.inspect.empty()) {
    d["inspect"] = Json::array();
    for (const std::string& o : info.inspect) d["inspect"].push_back(Json::parse(o));
  }
  d["conventions"] =
      "matrices column-major as glLoadMatrixf takes them; viewports in pixels from the top-left of the image; "
      "texture row 0 is t = 0; vertex tex is (s,t,r,q)";
  if (!info.renderer.empty()) d["renderer"] = info.renderer;
  std::vector<const Batch*> streamed;
  frameInto(d, f, true, streamed);

  std::string out = "{";
  Writer w(out, streamed);
  bool first = true;
  for (const auto& [k, v] : d.items()) {
    out += first ? "\n  " : ",\n  ";
    first = false;
    w.key(k);
    if (listPerLine(k) && v.is_array() && !v.empty()) {
      out += '[';
      for (size_t i = 0; i < v.size(); ++i) {
        out += i ? ",\n    " : "\n    ";
        w.emit(v[i], "    ");
      }
      out += "\n  ]";
    } else {
      w.emit(v, "  ");
    }
  }
  return out + "\n}\n";
}
}  // namespace ts
