// common/app/inspect_mode.cpp — see inspect_mode.hpp.
#include "common/app/inspect_mode.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "common/app/inspect_view.hpp"
#include "common/gl/render.hpp"

namespace ts {
namespace {
constexpr int kLoupe = 32;  // pixels a side around the pick
// The loupe's texture, owned by the renderer: deleted while its context is current.
struct Loupe : Renderer::Attachment {
  explicit Loupe(Renderer&) { glGenTextures(1, &id); }
  ~Loupe() override { glDeleteTextures(1, &id); }
  GLuint id = 0;
};
struct Cell : Loupe {
  using Loupe::Loupe;
};
constexpr int kCell = 256;  // the footprint cell's pixels a side

// An RGBA8 image (row 0 at the top, as ImGui draws it) into texture `id`.
void upload(GLuint id, const Image& img) {
  GLint prev = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &prev);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, GLuint(prev));
}
}  // namespace

InspectMode::InspectMode(const Options& opts, const CommonFlags& flags) {
  for (const auto& it : opts.items())
    if (it.key == 'i' || it.keyDown == 'i') key_ = 'I';
  if (!flags.inspect.empty()) {  // --inspect X,Y: open with it picked
    active_ = picked_ = stale_ = true;
    x_ = flags.inspect.front()[0], y_ = flags.inspect.front()[1];
  }
}

void InspectMode::toggle() {
  active_ = !active_;
  std::printf("inspect: %s\n", active_ ? "on (click a pixel of the figure)" : "off");
  std::fflush(stdout);
}

void InspectMode::click(double x, double y, int figureW, int height) {
  if (!active_ || x < 0 || y < 0 || x >= figureW || y >= height) return;
  x_ = int(x), y_ = int(y);
  picked_ = stale_ = true;
}

bool InspectMode::update(Renderer& r, const Frame& f, bool changed) {
  if (!active_ || !picked_ || (!stale_ && !changed)) return false;
  stale_ = false;
  if (x_ >= f.width || y_ >= f.height) {  // the figure shrank under the pick
    card_ = "the picked pixel " + std::to_string(x_) + "," + std::to_string(y_) + " is outside the figure now";
    ordinal_ = -1;
    return true;
  }
  // GL's pixels around the pick, from the back buffer the figure was just
  // drawn into, in one read of the part inside the figure (GL's rows run
  // bottom-up; the window's y runs down).
  Image around(kLoupe, kLoupe, {0, 0, 0, 255});
  const int left = x_ - kLoupe / 2, top = y_ - kLoupe / 2;
  const int rx0 = std::max(0, left), ry0 = std::max(0, top);
  const int rx1 = std::min(f.width, left + kLoupe), ry1 = std::min(f.height, top + kLoupe);
  std::vector<uint8_t> rgba(size_t(rx1 - rx0) * size_t(ry1 - ry0) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(rx0, f.height - ry1, rx1 - rx0, ry1 - ry0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  for (int y = ry0; y < ry1; ++y)
    for (int x = rx0; x < rx1; ++x) {
      const uint8_t* p = &rgba[(size_t(ry1 - 1 - y) * size_t(rx1 - rx0) + size_t(x - rx0)) * 4];
      around.set(x - left, y - top, {p[0], p[1], p[2], 255});
    }
  const Rgba gl = around.at(kLoupe / 2, kLoupe / 2);
  Image frameImage(f.width, f.height);  // only the picked pixel is read from it
  frameImage.set(x_, y_, gl);
  const Picked p = inspectPixels(f, frameImage, {{x_, y_}}).front();
  card_ = inspectCard(p);
  ordinal_ = -1;
  if (p.in.panel >= 0 && p.in.batch >= 0) {
    ordinal_ = p.in.batch;
    for (int k = 0; k < p.in.panel; ++k) ordinal_ += int(f.panels[size_t(k)].batches.size());
  }
  // The footprint: in the demo's own texture-space views when one shows the
  // texture, else on level 0 in the side panel.
  inViews_ = footprintInTextureViews(f, p.in, &over_);
  cell_ = 0;
  std::string where = "none (the pixel is not textured)";
  if (p.in.textured && p.in.texture >= 0) {
    // Level 0 around the footprint, magnified, in the side panel; in a view
    // of the whole texture a footprint is often a pixel or two.
    cell_ = r.attachment<Cell>().id;
    upload(cell_, r.renderOffscreen(footprintCell(f, p.in, kCell, kCell)));
    where = "on level 0 in the side panel";
  }
  for (const Panel& v : over_.panels) where += ", and in the view " + v.id.substr(0, v.id.size() - 10);
  std::printf("inspect: pixel %d,%d\n%sinspect: footprint %s\n", x_, y_, card_.c_str(), where.c_str());
  std::fflush(stdout);
  loupe_ = r.attachment<Loupe>().id;
  upload(loupe_, around);
  return true;
}

void InspectMode::drawFootprint(Renderer& r) const {
  if (active_ && picked_ && inViews_) r.drawOver(over_);
}

void InspectMode::drawPanel(float width) {
  if (!active_) return;
  ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "Inside a pixel (%c: off)", key_);
  if (!picked_ || card_.empty()) {
    ImGui::TextWrapped("Click a pixel of the figure: its footprint in the texture, lambda, the texels read and their "
                       "weights, the colour GL drew beside the reference's.");
    ImGui::Separator();
    return;
  }
  // The loupe and, beside it, the footprint on level 0 (side by side: the
  // card stays in view).
  const bool withCell = cell_ != 0;
  const float side = withCell ? std::min((width - 24.0f) / 2, 176.0f) : std::min(width - 16.0f, 192.0f);
  if (loupe_) {  // the loupe: 32 x 32 pixels, the grid, the pick outlined
    const float cell = side / kLoupe;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(loupe_)), ImVec2(side, side));
    ImDrawList* d = ImGui::GetWindowDrawList();
    for (int k = 0; k <= kLoupe; ++k) {
      d->AddLine(ImVec2(at.x + k * cell, at.y), ImVec2(at.x + k * cell, at.y + side), IM_COL32(0, 0, 0, 90));
      d->AddLine(ImVec2(at.x, at.y + k * cell), ImVec2(at.x + side, at.y + k * cell), IM_COL32(0, 0, 0, 90));
    }
    const ImVec2 c(at.x + (kLoupe / 2) * cell, at.y + (kLoupe / 2) * cell);
    d->AddRect(c, ImVec2(c.x + cell, c.y + cell), IM_COL32(255, 210, 60, 255), 0.0f, 0, 2.0f);
  }
  // Every colour the cell draws (footprintCell: footprintBatches over level 0's texel grid).
  const char* legend = "preimage of the pixel (white), derivatives (cyan), EWA ellipse (magenta), 2^lambda square "
                       "(yellow), texels read (orange), level 0's texels (grey grid, when they are large enough)";
  if (withCell) {
    if (loupe_) ImGui::SameLine();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(cell_)), ImVec2(side, side));
    ImGui::TextWrapped("Left: the pixels around the pick. Right: level 0 around its footprint%s: %s.",
                       inViews_ ? " (also drawn in the texture-space view)" : "", legend);
  }
  ImGui::TextWrapped("%s", card_.c_str());
  ImGui::Separator();
  // A ring round the pick on the figure (around it, not over it).
  ImGui::GetForegroundDrawList()->AddRect(ImVec2(float(x_) - 4, float(y_) - 4), ImVec2(float(x_) + 5, float(y_) + 5),
                                          IM_COL32(255, 210, 60, 255), 0.0f, 0, 2.0f);
}

std::string InspectMode::flag() const {
  return picked_ ? " --inspect " + std::to_string(x_) + "," + std::to_string(y_) : "";
}
}  // namespace ts
