#include "common/app/gl_pane.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "common/gl/render.hpp"

namespace ts {
int glPaneWidth(int windowWidth) {
  // About 40% of the window: a listing line is ~60 characters of 7 pixels;
  // never so wide that the figure gets less than half.
  return std::clamp(windowWidth * 2 / 5, std::min(240, windowWidth / 2), 620);
}

void GlPane::keyPressed(double now) {
  if (!calls_.empty()) baseline_ = calls_;
  keyAt_ = now;
  awaitingResult_ = true;
  markedSinceKey_ = false;
}

void GlPane::record(Renderer& r, const Frame& f, double now, bool print, bool result) {
  // The pictures the scene rendered itself first, then the frame's calls.
  std::vector<CallSection> calls = pictureSections(f, recordPicture(r, f));
  // Compared with the listing before the key until its marks have had their
  // time: re-recording (the measurement arrives, the window is resized)
  // must not clear them.
  const bool compare = !baseline_.empty() && (awaitingResult_ || now - keyAt_ < kHighlightSeconds ||
                                              (markedSinceKey_ && now - changedAt_ < kHighlightSeconds));
  std::vector<bool> picked;
  if (pick_ >= 0 && !calls.empty() && calls.back().calls) picked = batchTextureCalls(*calls.back().calls, pick_);
  lines_ = listing(calls, compare ? &baseline_ : nullptr, 3, picked.empty() ? nullptr : &picked);
  calls_ = std::move(calls);
  if (result) awaitingResult_ = false;
  firstChanged_ = -1;
  int changed = 0;
  for (size_t k = 0; k < lines_.size(); ++k)
    if (lines_[k].changed) {
      if (firstChanged_ < 0) firstChanged_ = int(k);
      if (print && ++changed <= 24) std::printf("gl pane: changed: %s\n", lines_[k].text.c_str());
    }
  firstPicked_ = -1;
  int marked = 0;
  for (size_t k = 0; k < lines_.size(); ++k)
    if (lines_[k].picked) {
      if (firstPicked_ < 0) firstPicked_ = int(k);
      if (print && pickNew_ && ++marked <= 40) std::printf("gl pane: picked: %s\n", lines_[k].text.c_str());
    }
  if (pickNew_ && firstPicked_ >= 0) scrollPick_ = true;  // a new pick scrolls to its calls
  if (print && pickNew_) std::printf("gl pane: %d lines set the picked pixel's texture state\n", marked);
  pickNew_ = false;
  if (print) {
    std::printf("gl pane: %zu lines, %d changed by the last key\n", lines_.size(), changed);
    std::fflush(stdout);
  }
  // The marks appear: they hold from now, scrolled into view.  The picture
  // with the key's numbers may mark other lines than the one before it
  // (quad_distortion d: a glViewport near the top, then vertices 200 lines
  // down), so that recording scrolls to its first marked line again.
  if (firstChanged_ >= 0 && (!markedSinceKey_ || result)) {
    if (!markedSinceKey_) changedAt_ = now;
    markedSinceKey_ = true;
    scroll_ = true;
  }
}

void GlPane::pick(int ordinal) {
  pick_ = ordinal;
  pickNew_ = ordinal >= 0;  // printed (and scrolled to) with the next recording
}

void GlPane::draw(int x, int w, int h, double now) {
  ImGui::SetNextWindowPos(ImVec2(float(x), 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(float(w), float(h)), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(1.0f);  // beside the figure: nothing shows through
  ImGui::Begin("OpenGL calls of this picture (l: hide)", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  bool fresh = now - changedAt_ < kHighlightSeconds;
  ImGui::TextWrapped("%zu lines, recorded as drawn. %s%s", lines_.size(),
                     fresh ? "Yellow: changed by the last key."
                           : "Press a key of the demo: what it changes turns yellow.",
                     firstPicked_ >= 0 ? " Cyan: the calls that set the picked pixel's texture state." : "");
  ImGui::Separator();
  ImGui::BeginChild("listing", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  float lineHeight = ImGui::GetTextLineHeightWithSpacing();
  const bool toChanged = scroll_ && firstChanged_ >= 0, toPicked = scrollPick_ && firstPicked_ >= 0;
  if (toChanged || toPicked) {
    const int line = toChanged ? firstChanged_ : firstPicked_;
    ImGui::SetScrollY(std::max(0.0f, float(line) * lineHeight - ImGui::GetWindowHeight() / 3));
    scroll_ = scrollPick_ = false;
  }
  ImGuiListClipper clipper;
  clipper.Begin(int(lines_.size()), lineHeight);
  while (clipper.Step())
    for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k) {
      const ListingLine& l = lines_[size_t(k)];
      if (l.changed && fresh) ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.2f, 1.0f), "%s", l.text.c_str());
      else if (l.picked) ImGui::TextColored(ImVec4(0.35f, 0.9f, 1.0f, 1.0f), "%s", l.text.c_str());
      else if (l.text.rfind("/*", 0) == 0 || l.text.rfind("    \"", 0) == 0)
        ImGui::TextColored(ImVec4(0.6f, 0.7f, 0.6f, 1.0f), "%s", l.text.c_str());
      else ImGui::TextUnformatted(l.text.c_str());
    }
  clipper.End();
  ImGui::EndChild();
  ImGui::End();
}
}  // namespace ts
