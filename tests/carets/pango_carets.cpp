// Writes Pango's carets for the bidi paragraphs of texts.txt, one case per
// line (carets.tsv), which tests/caret_test.cpp compares curvetext with:
//   pango_carets texts.txt > carets.tsv
// Columns, tab-separated: direction, the text, then for every caret position
// (grapheme boundary, UTF-8 offset i) "i:strong_x:weak_x" in px, then the
// positions a visual walk to the right visits from the line's left end, then
// those a walk to the left visits from its right end (Pango's
// pango_layout_move_cursor_visually with strong carets). DejaVu Sans at
// 20 px, unrounded glyph positions, no wrapping.
#include <pango/pangoft2.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

constexpr double kSizePx = 20.0;

struct Layout {
  PangoFontMap* map = pango_ft2_font_map_new();
  PangoContext* context = pango_font_map_create_context(map);
  PangoLayout* layout = nullptr;

  Layout(const std::string& direction, const std::string& text) {
    pango_context_set_round_glyph_positions(context, FALSE);
    if (direction != "auto")
      pango_context_set_base_dir(context, direction == "rtl" ? PANGO_DIRECTION_RTL : PANGO_DIRECTION_LTR);
    layout = pango_layout_new(context);
    pango_layout_set_auto_dir(layout, direction == "auto");
    PangoFontDescription* desc = pango_font_description_from_string("DejaVu Sans");
    pango_font_description_set_absolute_size(desc, kSizePx * PANGO_SCALE);
    pango_layout_set_font_description(layout, desc);
    pango_font_description_free(desc);
    pango_layout_set_text(layout, text.data(), static_cast<int>(text.size()));
  }
  ~Layout() {
    g_object_unref(layout);
    g_object_unref(context);
    g_object_unref(map);
  }
};

// Byte offsets of the caret positions (grapheme boundaries), start and end included.
std::vector<int> caret_positions(PangoLayout* layout, const std::string& text) {
  int n = 0;
  const PangoLogAttr* attrs = pango_layout_get_log_attrs_readonly(layout, &n);
  std::vector<int> out;
  const char* p = text.c_str();
  for (int i = 0; i < n; ++i) {
    if (attrs[i].is_cursor_position) out.push_back(static_cast<int>(p - text.c_str()));
    if (i + 1 < n) p = g_utf8_next_char(p);
  }
  return out;
}

// The walk of strong carets from one end of the line to the other.
std::vector<int> walk(PangoLayout* layout, const std::string& text, int direction) {
  int index = 0, trailing = 0;
  const int edge = direction > 0 ? -1 : 1 << 24;  // Pango units, beyond the line's left or right end
  pango_layout_xy_to_index(layout, edge, 0, &index, &trailing);
  std::vector<int> out;
  for (int guard = 0; guard < 1000; ++guard) {
    const char* at = g_utf8_offset_to_pointer(text.c_str() + index, trailing);
    out.push_back(static_cast<int>(at - text.c_str()));
    int next = 0, next_trailing = 0;
    pango_layout_move_cursor_visually(layout, TRUE, index, trailing, direction, &next, &next_trailing);
    if (next < 0 || next == G_MAXINT) break;
    index = next;
    trailing = next_trailing;
  }
  return out;
}

std::string joined(const std::vector<int>& v) {
  std::string s;
  for (int x : v) s += (s.empty() ? "" : " ") + std::to_string(x);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: pango_carets texts.txt > carets.tsv\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "pango_carets: cannot read %s\n", argv[1]);
    return 1;
  }
  std::printf("# Written by tests/carets/pango_carets.cpp from texts.txt (Pango %s); do not edit.\n",
              pango_version_string());
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos) continue;
    const std::string direction = line.substr(0, tab), text = line.substr(tab + 1);
    Layout l(direction, text);
    std::string carets;
    for (int i : caret_positions(l.layout, text)) {
      PangoRectangle strong, weak;
      pango_layout_get_cursor_pos(l.layout, i, &strong, &weak);
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s%d:%.3f:%.3f", carets.empty() ? "" : " ", i,
                    static_cast<double>(strong.x) / PANGO_SCALE, static_cast<double>(weak.x) / PANGO_SCALE);
      carets += buf;
    }
    std::printf("%s\t%s\t%s\t%s\t%s\n", direction.c_str(), text.c_str(), carets.c_str(),
                joined(walk(l.layout, text, 1)).c_str(), joined(walk(l.layout, text, -1)).c_str());
  }
  return 0;
}
