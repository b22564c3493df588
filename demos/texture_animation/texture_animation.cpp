// Textures that move (seed 001, "texture animation"): a waterfall scrolled by the texture matrix, a flipbook
// refilled by glTexSubImage2D, a torch of alpha flipbook frames drawn in the right order, and a light map
// recomputed each frame for a moving light.
//
// The waterfall's claim (view waterfall): a texture can move on a surface whose vertices and texture
// coordinates never change.  The texture matrix, which GL applies to every (s, t, r, q) before the lookup,
// translates t by speed x time; with GL_REPEAT the texture wraps, so the water falls without end.  The
// picture then moves by exactly the matrix's speed: from one frame to the next, every pixel shows what the pixel
// speed x frame time x pixels-a-texel above it showed, and nothing else.
//
// The flipbook's claim (view flipbook): a "video" texture is one texture made once (glTexImage2D with no data)
// whose texels each frame replaces with glTexSubImage2D, either whole (w h 4 bytes) or only the bounding
// rectangle of the texels that changed since the frame before (fewer bytes, the same picture): every pixel of
// every frame shown at 2 pixels a texel (GL_NEAREST) is its frame's texel (flipbook_mismatches = 0), not the
// next frame's (the control), and the bytes are counted from the recorded glTexSubImage2D calls.
//
// The torch's claim (view torch): alpha-textured flames (flipbook frames) over an opaque wall and handle come out
// right only drawn opaque first, then the transparent quads back to front with depth writes off; GL's picture
// then equals the CPU's layer-by-layer composite (torch_order_error_px[right] = 0), and the scene's order with
// depth written does not (the flames' clear texels write depth and hide what lies behind them).
//
// The moving light's claim (view lightmap): a 32 x 32 light map recomputed for the light's place each frame
// and re-uploaded by glTexSubImage2D stays within its bilinear interpolation's error of per-pixel lighting
// (dynamic_lightmap_rms_levels); the map computed at time 0 and left stale is further off once the light moved.
//
// Keys (each is also a flag, see --help):
//   v      view: waterfall | flipbook | torch | lightmap
//   a      animate: the window's clock runs the water, or steps --time a frame each quarter second in the
//          other views (after 30 frames still; figures and measurement: --time)
//   + / -  speed, texels a second           . / ,  the clock a frame on / back (--time, seconds: in every
//                                                  view the flipbook frame k, the torch's frames, the light)
//
// The equation, for a texture of h texels a side and a quad with t from 0 to 1:
//   (s', t') = T (s, t),  T = translate(0, speed time / h)     the texture matrix
//   pixel (x, y) at frame k+1 = pixel (x, y - d) at frame k,  d = speed x (1 / fps) x pixels a texel
// with y down the picture (the texel read at a pixel moves up the texture, so the water moves down) and
// y - d taken round the quad (it shows the whole texture, which repeats).
//
// What the GL does, all in common/gl/render.cpp (Renderer::draw of the frame's batches):
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT); GL_TEXTURE_MAG_FILTER GL_NEAREST;
//   glMatrixMode(GL_TEXTURE); glLoadMatrixf(T);   T is what glLoadIdentity(); glTranslatef(0, speed time / h, 0)
//   glMatrixMode(GL_MODELVIEW);                   makes: the translation, loaded whole
//   glBegin(GL_TRIANGLES); glTexCoord4f(s, t, 0, 1); glVertex3f(...) ... glEnd();
// Listing: book_figures/texture_animation_waterfall.gl.txt.
//
// The flipbook, torch and light equations (texture_animation_math.hpp), frame k = the whole quarter seconds in --time:
//   bytes(whole) = 64 x 64 x 4;  bytes(partial, k) = 4 |R_k|,
//   R_k = the bounding box of {(i, j): F_k(i, j) != F_k-1(i, j)}  (F_k: frame k's texels)
//   c = s a + d (1 - a)  per flame over what lies behind it, back to front (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
//   L(x, y) = a0 + (1 - a0) (h / d)^3, d = |light(t) - (x, y, 0)|, light(t) = (0.5 + r cos wt, 0.5 + r sin wt, h)
//   c = base x bilinear(L at the 32 x 32 texel centres)  (GL_MODULATE on unit 1)  against base x L per pixel
// What the GL does (texture_animation_gl.hpp, passes of measure() read back and shown as pictures):
//   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);   once
//   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
//   glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, texels);     each frame
//   opaque: glDisable(GL_BLEND); glDepthMask(GL_TRUE); ... then glEnable(GL_BLEND);
//   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); glDepthMask(GL_FALSE); flames back to front
//   glActiveTexture(GL_TEXTURE1); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  the light map
// Listings: book_figures/texture_animation_flipbook.gl.txt, texture_animation_torch.gl.txt,
// texture_animation_lightmap.gl.txt (each picture's recorded calls, then the frame's).
// The upload rate, whole against partial at 64^2, 256^2 and 1024^2: tests/bench/bench_upload.cpp (a benchmark).
//
// Measured (measure()): the quad alone rendered offscreen at kPixelsPerTexel pixels a texel, at frames k
// and k+1 (k the whole frames in --time, kFramesPerSecond a second: time is an option, not the wall
// clock, so the numbers and the figures are the same every run), read back; frame k moved down by d
// pixels against frame k+1, pixel for pixel: the pixels that differ (0), the same with the speed one
// texel a second too fast (d + 1 pixels: a control that must find some), and the shift that matches.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/gl/render.hpp"
#include "demos/texture_animation/texture_animation_textures.hpp"
#include "texture_animation_views.hpp"

namespace {
constexpr int kTexels = 32;          // the texture is kTexels x kTexels, and the quad shows it once
constexpr int kPixelsPerTexel = 4;   // in the measurement: each texel a 4 x 4 block of pixels
constexpr int kFramesPerSecond = 4;  // the measured frames are 1/4 s apart: d = speed pixels a frame
constexpr int kHoldFrames = 30;      // the window's animation waits this many frames before the clock runs
constexpr int kFramesShown = 2;      // the figure's frames: k and k+1, the two measured

// The texture matrix at `seconds`: t moves on speed x seconds texels.  Taken round the texture first
// (GL_REPEAT shows the same picture), so a float keeps every digit of the translation however long it runs.
glm::mat4 textureMatrix(int speed, double seconds) {
  const double texels = std::fmod(speed * seconds, double(kTexels));
  return glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, float(texels / kTexels), 0.0f));
}

// The quad over the whole panel, (s, t) from 0 to 1, its texture scrolled by `tm`.
ts::Panel quadPanel(const std::string& id, const ts::Rect& viewport, int texture, const glm::mat4& tm) {
  ts::Panel p = ts::layout::unitPanel(id, viewport);
  ts::Batch b;
  b.role = "waterfall";
  b.texture = texture;
  b.textureMatrix = tm;
  for (int k : {0, 1, 2, 0, 2, 3}) {
    const glm::vec2 c(k == 1 || k == 2, k >= 2);
    b.vertices.push_back({{c, 0.0f}, {c, 0.0f, 1.0f}, {1, 1, 1, 1}});
  }
  p.batches.push_back(b);
  return p;
}

// Pixels where `next` differs from `prev` moved down by `d` rows (round the picture).
int mismatches(const ts::Image& prev, const ts::Image& next, int d) {
  int n = 0;
  const int h = prev.height;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < prev.width; ++x) {
      const ts::Rgba a = prev.at(x, ((y - d) % h + h) % h), b = next.at(x, y);
      n += a.r != b.r || a.g != b.g || a.b != b.b;
    }
  return n;
}

class TextureAnimation final : public ts::Scene {
 public:
  std::string id() const override { return "texture_animation"; }
  std::string title() const override {
    return "Textures that move: a waterfall, a flipbook, a torch, a light map for a moving light";
  }
  std::string about() const override {
    return "A quad of water whose texture the texture matrix scrolls: glMatrixMode(GL_TEXTURE), a translation of t by\n"
           "speed x time, GL_REPEAT.  Measured from frames k and k+1 read back: the picture moved by exactly the\n"
           "matrix's speed (no pixel differs from the previous frame moved by it), and a wrong speed does not match.\n"
           "Views: a flipbook refilled by glTexSubImage2D (bytes a frame whole and partial, counted from the\n"
           "calls; every frame shown is its texels), a torch of alpha flipbook frames (pixels off the CPU's\n"
           "composite in the right and wrong orders), a 32x32 light map recomputed each frame for a moving light\n"
           "(RMS against per-pixel lighting, and with the map of time 0).";
  }
  std::vector<std::string> claim() const override {
    if (view_ == 1) return {"flipbook_bytes_per_frame*", "flipbook_mismatches*"};
    if (view_ == 2) return {"torch_order_error_px*"};
    if (view_ == 3) return {"dynamic_lightmap_rms_levels*"};
    return {"scroll_texel_mismatches", "scroll_texel_mismatches[wrong_speed]"};
  }
  void addOptions(ts::Options& o) override {
    o.addInt("speed", &speed_, 0, 16, "texels a second the texture matrix moves t by", '+', '-', 1);
    o.addFloat("time", &time_, 0.0f, 3600.0f, "the clock, seconds: the frames shown and measured", '.', ',',
               1.0f / kFramesPerSecond);
    o.addBool("animate", &animate_,
              "window: run the clock (the water falls; the other views step --time a frame each 1/4 s)", 'a');
    o.addEnum("view", &view_, {"waterfall", "flipbook", "torch", "lightmap"},
              "the texture matrix's waterfall | a flipbook by glTexSubImage2D | a torch (alpha flipbook, blending "
              "order) | a light map recomputed for a moving light",
              'v');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"texture_animation_waterfall",
         "Texture animation (seed 001)",
         "A waterfall: one quad, its texture coordinates fixed, the texture matrix translating t by speed x "
         "time (GL_REPEAT, GL_NEAREST). Two frames a quarter second apart: the water moves down by exactly "
         "the speed, and nothing else changes.",
         {"--speed", "2", "--time", "1.25"},
         960,
         440,
         "From one frame to the next the picture moves {scroll_shift_px[found]} pixels, as the matrix's speed "
         "gives ({scroll_shift_px[expected]}): {scroll_texel_mismatches} pixels differ; moved as a speed one "
         "texel a second faster would, {scroll_texel_mismatches[wrong_speed]} differ."},
        {"texture_animation_flipbook",
         "Texture animation: a flipbook (seed 001)",
         "A flame's eight frames played in one texture made once and refilled by glTexSubImage2D: the whole frame, "
         "or only the rectangle where it differs from the frame before.  Read back at 2 pixels a texel "
         "(GL_NEAREST), every pixel is its frame's texel.",
         {"--view", "flipbook", "--time", "1.25"},
         960,
         440,
         "A whole frame is {flipbook_bytes_per_frame[whole]} bytes, the changed rectangle "
         "{flipbook_bytes_per_frame[partial]} on average; {flipbook_mismatches} pixels differ from their frame's "
         "texels, {flipbook_mismatches[next_frame]} against the next frame's."},
        {"texture_animation_torch",
         "Texture animation: a torch (seed 001)",
         "Two alpha flames, flipbook frames, over an opaque wall and handle: drawn after the opaque layers, back "
         "to front with depth writes off, against the scene's order with depth writes on, and the CPU's composite.",
         {"--view", "torch", "--time", "1.25"},
         960,
         400,
         "In the right order {torch_order_error_px[right]} pixels differ from the CPU's composite, in the scene's "
         "order {torch_order_error_px[wrong]}."},
        {"texture_animation_lightmap",
         "Texture animation: a light map for a moving light (seed 001)",
         "A wall lit by a point light circling over it: per-pixel lighting on the CPU; the 32 x 32 light map "
         "recomputed for the light and re-uploaded by glTexSubImage2D each frame; the map left as it was at time 0.",
         {"--view", "lightmap", "--time", "1.25"},
         960,
         400,
         "Against per-pixel lighting: {dynamic_lightmap_rms_levels} levels RMS with the map recomputed each frame, "
         "{dynamic_lightmap_rms_levels[stale]} with the stale one."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;
  ts::Frame buildAnimation(ts::Frame& f, const ts::Measurements& measured) const;
  // The window's clock runs after kHoldFrames frames still at --time, so the first pictures after the key
  // are the --png render's (the window tests compare them), as mipmap_popping's animation does.
  // The other views' pictures are GL passes of measure(): animated, the clock steps --time a frame on
  // every 1/kFramesPerSecond seconds, and the view turns live (measure() each frame, the window's thread),
  // which renders only when the frame changed.
  void update(double seconds) override {
    if (!animate_) {
      heldFrames_ = 0, clock_ = 0, stepClock_ = 0;
      return;
    }
    if (++heldFrames_ <= kHoldFrames) return;
    if (view_ == 0) {
      clock_ += seconds;
      return;
    }
    stepClock_ += seconds;
    if (stepClock_ < 1.0 / kFramesPerSecond) return;
    stepClock_ = 0;
    time_ = float(std::fmod(double(time_) + 1.0 / kFramesPerSecond, 3600.0));
  }
  bool animating() const override { return animate_; }
  bool live() const override { return animate_ && view_ > 0; }

 private:
  // The first measured frame: the whole frames in --time.
  int firstFrame() const { return int(std::floor(double(time_) * kFramesPerSecond + 1e-6)); }
  int speed_ = 2, view_ = 0;
  float time_ = 0;
  bool animate_ = false;
  double clock_ = 0;      // the window's running clock, seconds (animate)
  double stepClock_ = 0;  // seconds since the last step of --time (animate, the other views)
  int heldFrames_ = 0;
  // The live views' last measurement and the (view, time) it is of: measured again only when they change.
  ts::Measurements lastAnimation_;
  std::pair<int, float> lastAnimationOf_{-1, -1.0f};
};

ts::Frame TextureAnimation::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  if (view_ > 0) return buildAnimation(f, measured);
  const int k = firstFrame();
  const L::Text d = L::measured(measured, "scroll_shift_px[expected]", "%.0f");
  // The captions first: the cells take the lines they need (a narrow window wraps them).
  std::vector<L::Text> titles, matrices;
  std::vector<glm::mat4> tms;
  for (int i = 0; i < kFramesShown; ++i) {
    // The window's clock runs on from the frame; the figures' is still (clock_ = 0).
    const double seconds = double(k + i) / kFramesPerSecond + clock_;
    tms.push_back(textureMatrix(speed_, seconds));
    titles.push_back("frame " + L::given("frame number", k + i, "%.0f") + ", time " +
                     L::given("time, seconds", seconds, "%.2f") + " s");
    matrices.push_back("texture matrix: translate t by " +
                       L::given("the texture matrix's translation of t", tms.back()[3][1], "%.4f"));
  }
  const std::vector<std::vector<L::Text>> below = {
      {"speed " + L::given("speed, texels a second", speed_, "%.0f") + " texels/s x " +
           L::given("seconds a frame", 1.0 / kFramesPerSecond, "%.2f") + " s x " +
           L::given("pixels a texel in the measurement", kPixelsPerTexel, "%.0f") + " px a texel",
       "= " + d + " px a frame, down"},
      {L::measuredText(measured, "frame k moved {scroll_shift_px[expected]|%.0f} px: "
                                 "{scroll_texel_mismatches|%.0f} pixels differ;"),
       L::measuredText(measured, "moved {scroll_shift_px[wrong_speed]|%.0f} px (1 texel/s too fast): "
                                 "{scroll_texel_mismatches[wrong_speed]|%.0f} differ;"),
       L::measuredText(measured, "first match at {scroll_shift_px[found]|%.0f} px")}};
  L::FlowSpec spec;
  spec.n = kFramesShown, spec.linesAbove = 2, spec.linesBelow = 3, spec.gap = 8;
  std::vector<L::Stack> above, under;
  for (int i = 0; i < kFramesShown; ++i) {
    above.push_back({titles[size_t(i)].text, matrices[size_t(i)].text});
    under.emplace_back();
    for (const L::Text& t : below[size_t(i)]) under.back().push_back(t.text);
  }
  const std::vector<L::Cell> cells = L::flowFitting({6, 6, float(width) - 6, float(height) - 6}, spec, above, under);
  const int tex = f.addTexture(ts::texanim::waterTexture(kTexels));
  for (int i = 0; i < kFramesShown; ++i) {
    const L::Cell& c = cells[size_t(i)];
    f.panels.push_back(quadPanel("frame_" + std::to_string(i), c.picture, tex, tms[size_t(i)]));
    // The title's lines, then the matrix's (at the figure's size, the two halves of a two-line band).
    const auto [upper, lower] = L::stackApart(c.above, c.scale, matrices[size_t(i)].text);
    L::caption(f, upper, titles[size_t(i)], L::kWhite, c.scale);
    L::caption(f, lower, matrices[size_t(i)], L::kWhite, c.scale);
    L::phrases(f, c.below, below[size_t(i)], L::kAmber, c.scale);
  }
  return f;
}

ts::Measurements TextureAnimation::measure(ts::Renderer& r) {
  if (view_ > 0) {
    if (lastAnimationOf_ == std::make_pair(view_, time_)) return lastAnimation_;
    ts::Measurements out;
    out.detail = ts::texanim::measureAnimations(r, firstFrame(), time_, 1.0 / kFramesPerSecond, out);
    lastAnimationOf_ = {view_, time_}, lastAnimation_ = out;
    return out;
  }
  const int n = kTexels * kPixelsPerTexel;
  auto frame = [&](int k) {
    ts::Frame f;
    f.width = f.height = n;
    const int tex = f.addTexture(ts::texanim::waterTexture(kTexels));
    f.panels.push_back(quadPanel("quad", {0, 0, n, n}, tex, textureMatrix(speed_, double(k) / kFramesPerSecond)));
    return r.renderOffscreen(f);  // row 0 at the top
  };
  const int k = firstFrame();
  const ts::Image prev = frame(k), next = frame(k + 1);
  // d = speed texels a second x 1/fps seconds x pixels a texel: whole pixels for any whole speed.
  const int expected = speed_ * kPixelsPerTexel / kFramesPerSecond;
  const int wrong = (speed_ + 1) * kPixelsPerTexel / kFramesPerSecond;
  int found = -1;  // the first shift down the picture at which every pixel matches
  for (int d = 0; d < n && found < 0; ++d)
    if (mismatches(prev, next, d) == 0) found = d;
  ts::Measurements out;
  out.push_back({"scroll_texel_mismatches", double(mismatches(prev, next, expected)),
                 "pixels of frame k+1 that differ from frame k moved down by the matrix's speed"});
  out.push_back({"scroll_texel_mismatches[wrong_speed]", double(mismatches(prev, next, wrong)),
                 "the same, frame k moved as a speed one texel a second faster would move it (a control)"});
  out.push_back({"scroll_shift_px[expected]", double(expected),
                 "pixels the picture moves a frame: speed x frame time x pixels a texel"});
  out.push_back({"scroll_shift_px[wrong_speed]", double(wrong), "pixels a speed one texel a second faster moves"});
  out.push_back({"scroll_shift_px[found]", double(found),
                 "the smallest shift down the picture at which frame k matches frame k+1 everywhere (-1: none)"});
  out.push_back({"scroll_frame_changed_pixels", double(mismatches(prev, next, 0)),
                 "pixels that differ between frames k and k+1 unmoved: the texture did move"});
  return out;
}

// The flipbook, the torch and the moving light: pictures measure() rendered (texture_animation_views.hpp).
ts::Frame TextureAnimation::buildAnimation(ts::Frame& f, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  namespace ta = ts::texanim;
  const ta::Pictures* p = measured.detailAs<ta::Pictures>();
  if (!p) {
    L::caption(f, {8, 8, float(f.width - 8), float(f.height - 8)}, "rendering ...", L::kWhite, 2);
    return f;
  }
  auto M = [&](const std::string& templ) { return L::measuredText(measured, templ); };
  const int k = firstFrame() % ta::kFlipFrames;
  const L::Text frameK = L::given("the flipbook frame shown", k, "%.0f");
  const L::Text frameNext = L::given("the next flipbook frame", (k + 1) % ta::kFlipFrames, "%.0f");
  if (view_ == 1) {
    ta::pictureRow(
        f,
        {{&p->flipWhole, "frame " + frameK + ": whole upload",
          M("{flipbook_bytes_per_frame[whole]|%.0f} bytes a frame")},
         {&p->flipPartial, "frame " + frameNext + ": partial upload",
          M("{flipbook_bytes_shown[partial]|%.0f} bytes: {flipbook_rect_w|%.0f} x {flipbook_rect_h|%.0f} texels")},
         {&p->flipChanges, "what changed, " + frameK + " to " + frameNext,
          M("{flipbook_changed_texels|%.0f} texels changed")}},
        {{ta::kChanged, "a texel that differs from the frame before"},
         {ta::kUploaded, "the rectangle the partial glTexSubImage2D sends"}},
        M("Bytes a frame, counted from the calls: whole {flipbook_bytes_per_frame[whole]|%.0f}, partial "
          "{flipbook_bytes_per_frame[partial]|%.0f} (mean of the {flipbook_uploads|%.0f} uploads but the first).  ") +
            M("Pixels not their frame's texel: {flipbook_mismatches|%.0f}; against the next frame's: "
              "{flipbook_mismatches[next_frame]|%.0f}."));
  } else if (view_ == 2) {
    ta::pictureRow(
        f,
        {{&p->torchRight, "opaque, then back to front", M("{torch_order_error_px[right]|%.0f} pixels off the CPU")},
         {&p->torchWrong, "scene's order, depth on", M("{torch_order_error_px[wrong]|%.0f} pixels off")},
         {&p->torchCpu, "the CPU's composite", "wall, handle, flames"},
         {&p->torchWrongMask, "the scene's order: pixels off", M("{torch_order_error_px[wrong]|%.0f} red")}},
        {{ta::kWrong,
          "a pixel over " + std::to_string(2 * ta::kTorchLevelsPerLayer) + " levels off the CPU's composite"}},
        "Right: wall and handle with depth writes on; then glDepthMask(GL_FALSE), blending (GL_SRC_ALPHA, "
        "GL_ONE_MINUS_SRC_ALPHA), flames back to front.  Wrong: front flame, back flame, handle, wall, depth "
        "written: the flames' clear texels hide what lies behind them.  " +
            M("Flames front to back, depth writes off: {torch_order_error_px[front_to_back]|%.0f} pixels off.  ") +
            "Flame frames " + L::given("the back flame's frame", ta::backFlameFrame(firstFrame()), "%.0f") + " and " +
            L::given("the front flame's frame", ta::frontFlameFrame(firstFrame()), "%.0f") + ".");
  } else {
    ta::pictureRow(
        f,
        {{&p->litCpu, "per-pixel lighting (CPU)", "time " + L::given("time, seconds", double(time_), "%.2f") + " s"},
         {&p->litDynamic, "recomputed each frame", M("RMS {dynamic_lightmap_rms_levels|%.2f} levels")},
         {&p->litStale, "map of time 0 (stale)", M("RMS {dynamic_lightmap_rms_levels[stale]|%.2f} levels")},
         {&p->lightMap,
          "the light map, " + L::given("the light map's side, texels", ta::kLightTexels, "%.0f") + " x " +
              L::given("the light map's side, texels", ta::kLightTexels, "%.0f"),
          M("{lightmap_bytes_per_frame|%.0f} bytes a frame")}},
        {{ta::kLightNow, "the light now"}, {ta::kLightThen, "the light at time 0 (the stale map's)"}},
        "c = base x L: unit 0 the wall (GL_REPLACE), unit 1 the light map (GL_MODULATE, GL_LINEAR), refilled by "
        "glTexSubImage2D each frame; L = " +
            L::given("ambient", ta::kAmbient, "%.2f") + " + " + L::given("1 - ambient", 1 - ta::kAmbient, "%.2f") +
            " (h/d)^3, the light at height " + L::given("the light's height", ta::kLightHeight, "%.2f") +
            M(", moved {light_moved|%.3f} since time 0; the map's bilinear error alone: "
              "{dynamic_lightmap_rms_levels[predicted]|%.2f} levels."));
  }
  return f;
}
}  // namespace

TS_REGISTER_SCENE(TextureAnimation);
