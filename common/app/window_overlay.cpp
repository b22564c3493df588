// common/app/window_overlay.cpp — the Dear ImGui overlay: the side panel, the GL pane and the help card.
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "common/app/window_parts.hpp"

namespace ts::window_parts {
namespace {
// The help card (? or F1): the figure's claim, what to look for, every key.
void drawHelp(Scene& scene, const Options& opts, int w, int h, bool* open, char inspectKey) {
  float cw = std::min(float(w) - 40.0f, 720.0f), ch = std::min(float(h) - 40.0f, 560.0f);
  ImGui::SetNextWindowPos(ImVec2((float(w) - cw) / 2, (float(h) - ch) / 2), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(cw, ch), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.95f);
  ImGui::Begin("Help (? or F1 or Esc closes it)", open,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", scene.title().c_str());
  ImGui::Separator();
  std::string about = scene.about();  // single line breaks of the source are spaces here
  for (size_t k = 0; k + 1 < about.size(); ++k)
    if (about[k] == '\n' && about[k + 1] != '\n' && (k == 0 || about[k - 1] != '\n')) about[k] = ' ';
  ImGui::TextWrapped("%s", about.c_str());
  ImGui::Separator();
  ImGui::TextUnformatted("The demo's keys (each is also a flag: --help lists them):");
  for (const auto& it : opts.items()) {
    if (!it.key && !it.keyDown) continue;
    std::string keys = it.keyDown ? std::string(1, it.key) + "/" + std::string(1, it.keyDown) : std::string(1, it.key);
    ImGui::Bullet();
    ImGui::TextWrapped("%s  %s: %s", keys.c_str(), it.name.c_str(), it.help.c_str());
  }
  ImGui::Separator();
  ImGui::TextWrapped("Window keys: arrows turn and tilt (where the demo has them), = acts as +, Backspace resets "
                     "every option, a left drag orbits and the wheel zooms (3D views: --yaw, --pitch, --zoom), a "
                     "picture file dropped on the window is mapped (--texture), F12 saves the picture and its "
                     "sidecar and prints the command that remakes them, l shows the OpenGL calls beside the picture, "
                     "h hides the side panel, ? or F1 this card, Esc or q quits.");
  ImGui::TextWrapped("%c inspects a pixel: click one of the figure, and the side panel shows it magnified and what "
                     "happens inside it: (s,t,r,q), the derivatives, rho, lambda, the mip levels, the texels read "
                     "and their weights, the reference's colour beside GL's, and its footprint on the texture (also "
                     "in a texture-space view, where the demo has one); with the GL pane open (l), the calls that "
                     "set its texture turn cyan (--inspect X,Y does it from the command line).",
                     inspectKey);
  if (opts.has("pixel"))
    ImGui::TextWrapped("Outside the inspect mode a click on a raster picks its pixel (--pixel X,Y).");
  if (opts.has("light1-az") && opts.has("light1-el"))
    ImGui::TextWrapped("A right drag moves light 1 (--light1-az left and right, --light1-el up and down).");
  ImGui::End();
}

// Dear ImGui's draw lists, drawn with fixed-function vertex arrays through
// the suite's own GL pointers (the stock OpenGL backends bind GL themselves).
void drawImGui(ImDrawData* d, int fbw, int fbh) {
  glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_TRANSFORM_BIT | GL_SCISSOR_BIT | GL_TEXTURE_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glViewport(0, 0, fbw, fbh);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  const float left = d->DisplayPos.x, right = left + d->DisplaySize.x;
  const float top = d->DisplayPos.y, bottom = top + d->DisplaySize.y;
  glOrtho(left, right, bottom, top, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  ImVec2 scale = d->FramebufferScale;
  for (int n = 0; n < d->CmdListsCount; ++n) {
    const ImDrawList* list = d->CmdLists[n];
    const ImDrawVert* vb = list->VtxBuffer.Data;
    const ImDrawIdx* ib = list->IdxBuffer.Data;
    glVertexPointer(2, GL_FLOAT, sizeof(ImDrawVert), &vb->pos);
    glTexCoordPointer(2, GL_FLOAT, sizeof(ImDrawVert), &vb->uv);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(ImDrawVert), &vb->col);
    for (const ImDrawCmd& c : list->CmdBuffer) {
      if (c.UserCallback) continue;
      float x0 = (c.ClipRect.x - d->DisplayPos.x) * scale.x, y0 = (c.ClipRect.y - d->DisplayPos.y) * scale.y;
      float x1 = (c.ClipRect.z - d->DisplayPos.x) * scale.x, y1 = (c.ClipRect.w - d->DisplayPos.y) * scale.y;
      if (x1 <= x0 || y1 <= y0) continue;
      glScissor(int(x0), int(float(fbh) - y1), int(x1 - x0), int(y1 - y0));
      glBindTexture(GL_TEXTURE_2D, GLuint(reinterpret_cast<intptr_t>(c.GetTexID())));
      glDrawElements(GL_TRIANGLES, GLsizei(c.ElemCount), sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                     ib + c.IdxOffset);
    }
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glPopAttrib();
}
}  // namespace

// Starts Dear ImGui on the window (side panel, GL pane, help card) and
// uploads its font atlas; returns that texture, which closeWindow deletes.
GLuint startImGui(GLFWwindow* win) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;     // no imgui.ini left in the student's folder
  ImGui_ImplGlfw_InitForOpenGL(win, true);  // chains to the callbacks of connectInput
  GLuint fontTex = 0;
  unsigned char* px = nullptr;
  int w = 0, h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&px, &w, &h);
  glGenTextures(1, &fontTex);
  glBindTexture(GL_TEXTURE_2D, fontTex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(intptr_t(fontTex)));
  return fontTex;
}

// The side panel, the GL pane and the help card (Dear ImGui), each if open.
void FrameLoop::drawOverlay() {
  inspect.drawFootprint(renderer);  // key i: the pick's footprint in the figure's texture-space views
  bool imgui = input.overlay || pane.visible || input.help;
  if (imgui) {
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
  }
  if (pane.visible) pane.draw(split.paneX, split.paneW, ctx.height(), now);
  if (input.overlay) {
    PanelStatus status;
    status.fps = fps;
    status.idle = !busy && !measuring;
    status.paced = !busy && aloneWhileMeasuring();
    // The measurement's status: running, how far, and whether the numbers shown are an older state's.
    status.measuring = measuring;
    status.progress = measuring ? worker->progress() : 0.0;
    status.stale = measuring && !m.empty();
    drawSidePanel(scene, opts, m, status, split.panelX, split.panelW, ctx.height(),
                  [&] { inspect.drawPanel(float(split.panelW)); });
  }
  if (input.help) drawHelp(scene, opts, ctx.width(), ctx.height(), &input.help, inspect.key());
  if (imgui) {
    ImGui::Render();
    drawImGui(ImGui::GetDrawData(), ctx.width(), ctx.height());
  }
}
}  // namespace ts::window_parts
