// The text a headless ImGui frame drew, read back from its draw lists: each glyph is a quad whose texture
// coordinates are its glyph's in the font atlas (ImFont::RenderText), so the quads name the characters and where they
// stand. This sees text drawn straight into a draw list (ImDrawList::AddText) as well as widgets' labels, which
// ImGui's own logging does not. ASCII only; glyphs cut by a clip rectangle are not read.
#pragma once

#include <imgui.h>
#include <imgui_internal.h>  // ImGuiContext::Windows

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace somicage::editor {

// A run of text on one line: glyphs one space or less apart (a wider gap starts another run).
struct DrawnText {
  std::string text;
  ImVec2 pos;  // the pen position of its first glyph (what ImDrawList::AddText was given)
};

inline std::vector<DrawnText> drawnText(const ImDrawList& list) {
  const ImFont* font = ImGui::GetFont();
  struct Glyph {
    char c;
    float x, y, advance;
  };
  std::vector<Glyph> glyphs;
  for (int v = 0; v + 3 < list.VtxBuffer.Size; ++v) {
    const ImDrawVert& a = list.VtxBuffer[v];
    const ImDrawVert& c = list.VtxBuffer[v + 2];
    for (char ch = 33; ch < 127; ++ch) {
      const ImFontGlyph* g = font->FindGlyphNoFallback(static_cast<ImWchar>(ch));
      if (g && a.uv.x == g->U0 && a.uv.y == g->V0 && c.uv.x == g->U1 && c.uv.y == g->V1) {
        glyphs.push_back({ch, a.pos.x - g->X0, a.pos.y - g->Y0, g->AdvanceX});
        v += 3;
        break;
      }
    }
  }
  std::sort(glyphs.begin(), glyphs.end(),
            [](const Glyph& p, const Glyph& q) { return p.y != q.y ? p.y < q.y : p.x < q.x; });
  const float space = font->FindGlyph(' ')->AdvanceX;
  std::vector<DrawnText> runs;
  for (std::size_t k = 0; k < glyphs.size(); ++k) {
    const Glyph& g = glyphs[k];
    const float gap = k > 0 ? g.x - (glyphs[k - 1].x + glyphs[k - 1].advance) : 0.0f;
    if (k == 0 || g.y != glyphs[k - 1].y || gap > 1.5f * space || gap < -0.5f) {
      runs.push_back({std::string(1, g.c), ImVec2(g.x, g.y)});
    } else {
      if (gap > 0.5f * space) runs.back().text += ' ';
      runs.back().text += g.c;
    }
  }
  return runs;
}

// Where `text` was drawn as a whole run in any window active in this frame (the first found); none: nullopt.
inline std::optional<ImVec2> whereDrawn(const std::string& text) {
  for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
    if (!window->Active || !window->DrawList) continue;
    for (const DrawnText& run : drawnText(*window->DrawList))
      if (run.text == text) return run.pos;
  }
  return std::nullopt;
}

}  // namespace somicage::editor
