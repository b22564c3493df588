#include "common/app/side_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "common/app/gl_pane.hpp"

namespace ts {
int sidePanelWidth(int windowWidth) {
  // A state line is ~36 characters of 7 pixels; never more than a third of
  // the window, so the figure keeps the larger part.
  return std::clamp(windowWidth * 3 / 10, std::min(200, windowWidth / 3), 340);
}

WindowSplit splitWindow(int windowWidth, bool panelOpen, bool paneOpen) {
  WindowSplit s;
  s.paneW = paneOpen ? glPaneWidth(windowWidth) : 0;
  s.panelW = panelOpen ? sidePanelWidth(windowWidth) : 0;
  s.figureW = std::max(1, windowWidth - s.paneW - s.panelW);
  s.panelX = s.figureW;
  s.paneX = s.figureW + s.panelW;
  return s;
}

std::vector<const Measurement*> claimed(const Scene& scene, const Measurements& m) {
  std::vector<const Measurement*> out;
  for (const std::string& name : scene.claim()) {
    bool prefix = !name.empty() && name.back() == '*';  // "kink_deg*": every variant's
    std::string stem = prefix ? name.substr(0, name.size() - 1) : name;
    for (const auto& x : m)
      if (prefix ? x.name.compare(0, stem.size(), stem) == 0 : x.name == name) {
        if (std::find(out.begin(), out.end(), &x) == out.end()) out.push_back(&x);
        if (!prefix) break;
      }
  }
  if (out.empty())
    for (size_t k = 0; k < m.size() && k < 2; ++k) out.push_back(&m[k]);
  return out;
}

namespace {
std::string number(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
}  // namespace

void drawSidePanel(const Scene& scene, const Options& opts, const Measurements& m, const PanelStatus& status, int x,
                   int w, int h, const std::function<void()>& extra) {
  ImGui::SetNextWindowPos(ImVec2(float(x), 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(float(w), float(h)), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(1.0f);  // beside the figure: nothing shows through
  ImGui::Begin("##side_panel", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoTitleBar);
  const ImVec4 gold(1.0f, 0.85f, 0.35f, 1.0f), dim(0.65f, 0.65f, 0.7f, 1.0f), stale(0.6f, 0.6f, 0.6f, 1.0f);
  ImGui::TextWrapped("%s", scene.title().c_str());
  ImGui::Separator();
  if (extra) extra();  // the inspect mode, when on: first, where the student looks
  // The claim: its numbers large, each with what it means.
  if (status.measuring) ImGui::TextColored(gold, "measuring... %.0f%%", 100.0 * std::clamp(status.progress, 0.0, 1.0));
  if (m.empty() && !status.measuring) ImGui::TextColored(dim, "not measured yet");
  for (const Measurement* c : claimed(scene, m)) {
    // Wrapped: a long name ("moving_ball_error_px[static]") runs past a narrow window's panel otherwise.
    ImGui::PushStyleColor(ImGuiCol_Text, status.stale ? stale : gold);
    ImGui::TextWrapped("%s", c->name.c_str());
    ImGui::PopStyleColor();
    ImGui::SetWindowFontScale(2.0f);
    ImGui::TextColored(status.stale ? stale : gold, "%s%s", number(c->value).c_str(), status.stale ? " (stale)" : "");
    ImGui::SetWindowFontScale(1.0f);
    if (!c->meaning.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, dim);
      ImGui::TextWrapped("%s", c->meaning.c_str());
      ImGui::PopStyleColor();
    }
  }
  // A demo opened with a student's code (--seam mine, ...): the exercise's
  // checks, each line as the checker prints it (common/core/student_code.hpp).
  for (const auto& x : m)
    if (x.name.rfind("exercise_check[", 0) == 0) {
      const bool pass = x.value > 0.5;
      ImGui::TextColored(status.stale ? stale
                         : pass       ? ImVec4(0.45f, 0.9f, 0.45f, 1)
                                      : ImVec4(1, 0.45f, 0.4f, 1),
                         "%s", pass ? "pass" : "FAIL");
      ImGui::SameLine();
      std::string line = x.meaning;  // the verdict is in front: not again at the end
      for (const char* tail : {": pass", ": FAIL"})
        if (line.size() > 6 && line.compare(line.size() - 6, 6, tail) == 0) line.resize(line.size() - 6);
      ImGui::TextWrapped("%s", line.c_str());
    }
  ImGui::Separator();
  // The state, each option with the keys that change it (right-aligned;
  // on a line of their own when the panel is too narrow for both).
  auto state = opts.state();
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  for (const auto& it : opts.items()) {
    std::string value;
    for (const auto& [n, v] : state)
      if (n == it.name) value = v;
    char padded[256];
    std::snprintf(padded, sizeof padded, "%-12s %s", it.name.c_str(), value.c_str());
    std::string line = ImGui::CalcTextSize(padded).x <= ImGui::GetContentRegionAvail().x ? padded
                                                                                         : it.name + " " + value;
    std::string keys = !it.key && !it.keyDown ? ""
                       : it.keyDown           ? std::string(1, it.key) + "/" + std::string(1, it.keyDown)
                                              : std::string(1, it.key);
    float avail = ImGui::GetContentRegionAvail().x, need = ImGui::CalcTextSize(keys.c_str()).x;
    ImGui::TextWrapped("%s", line.c_str());
    if (keys.empty()) continue;
    if (ImGui::CalcTextSize(line.c_str()).x + spacing + need <= avail)
      ImGui::SameLine(avail - need + ImGui::GetStyle().WindowPadding.x);
    else ImGui::SetCursorPosX(ImGui::GetCursorPosX() + std::max(0.0f, avail - need));
    ImGui::TextColored(dim, "%s", keys.c_str());
  }
  ImGui::TextColored(dim, "%-12s %.1f%s", "fps", status.fps,
                     status.idle    ? " (idle)"
                     : status.paced ? " (measuring)"
                                    : "");
  ImGui::PushStyleColor(ImGuiCol_Text, dim);
  ImGui::TextWrapped("h: hide this panel  l: OpenGL calls  ?: help  F12: save  Backspace: reset  q: quit");
  ImGui::PopStyleColor();
  ImGui::Separator();
  // Everything measured, folded away.
  std::string header = "All " + std::to_string(m.size()) + " measurements###all_measurements";
  if (ImGui::CollapsingHeader(header.c_str())) {
    for (const auto& x : m) {
      ImGui::TextColored(status.stale ? stale : ImVec4(1, 1, 1, 1), "%s", x.name.c_str());
      ImGui::SameLine();
      ImGui::TextColored(status.stale ? stale : ImVec4(1, 1, 1, 1), "%s", number(x.value).c_str());
      if (!x.meaning.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", x.meaning.c_str());
    }
  }
  ImGui::End();
}
}  // namespace ts
