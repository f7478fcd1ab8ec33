// Paragraph layout speed against Pango (pangoft2) on the same texts, font
// file, size and width, in one run; and, with --check-breaks, a comparison of
// where the two break lines (run by CTest as layout_pango_breaks).
//
//   build/bench/layout_bench                 paragraphs/s for both, and the ratio:
//                                            Latin (English, German; DejaVu Sans), then
//                                            Arabic with Latin and digits, Hebrew,
//                                            Devanagari, Thai, CJK (Noto fonts)
//   build/bench/layout_bench --check-breaks  line starts, ours vs Pango's
//   build/bench/layout_bench --check-scripts per script (Thai, Lao, Khmer and
//                                            Myanmar without spaces too), over
//                                            several widths
//
// Both lay out from scratch each time (text set, itemised, shaped, broken);
// both keep their font caches warm (a FontCollection / a PangoFontMap), as an
// application would. Both use the same font files: curvetext gets the files,
// Pango the family names fontconfig resolves to them, and the files each side
// actually used are printed and compared.
#include <pango/pangoft2.h>

#include <pango/pangofc-font.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "curvetext/layout.hpp"
#include "curvetext/line_break.hpp"

namespace {

constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kFontFamily = "DejaVu Sans";  // fontconfig resolves it to kFontFile
constexpr double kSize = 16.0;
constexpr double kWidth = 420.0;

const std::vector<std::string>& english() {
  static const std::vector<std::string> t = {
      "It was the best of times, it was the worst of times, it was the age of wisdom, it was the age of foolishness, "
      "it was the epoch of belief, it was the epoch of incredulity, it was the season of Light, it was the season of "
      "Darkness, it was the spring of hope, it was the winter of despair.",
      "A text layout engine takes a paragraph and a width and returns positioned glyphs: it itemises the text by "
      "direction, script and font, shapes each item, finds the line break opportunities of UAX #14, and fills lines "
      "greedily, re-shaping only where a break falls inside a shaping context (e.g. a ligature or a kerning pair).",
      "The quick brown fox jumps over the lazy dog; pack my box with five dozen liquor jugs! How vexingly quick daft "
      "zebras jump - sphinx of black quartz, judge my vow. 1,234.56 dollars (about 1.2e3) were paid on 2023-05-04 at "
      "10:30 a.m.; see https://example.com/some/long/path?query=value&other=thing for details.",
      "Well-known, state-of-the-art, user-friendly tools \"quote\" their sources [1], (2) and {3}; others don't. "
      "Mr. Smith's well-being - and his co-workers' - was, in a word, non-negotiable.",
      "Prices rose 12% (from $3.50 to $3.92) in Q3/2023 \u2014 see pp. 12\u201314, e.g. \u201cTable 2\u201d \u2013 and "
      "the and/or clause; 50\u00a0km/h limits apply to long-distance lorries on the A1/A7 interchange.",
  };
  return t;
}

const std::vector<std::string>& german() {
  static const std::vector<std::string> t = {
      "Die Donaudampfschifffahrtsgesellschaftskapitänsmütze liegt auf dem Tisch, während draußen die "
      "Straßenbahn über die Brücke fährt und die Kinder im Schnee spielen.",
      "Überall dieselbe alte Leier: Das Wetter ist schlecht, die Bahn ist verspätet, und der Kaffee ist kalt. "
      "Trotzdem gehen wir jeden Morgen um halb acht ins Büro – zumindest die meisten von uns.",
      "Sprachwissenschaftlerinnen untersuchen Zusammensetzungen wie „Rechtsschutzversicherungsgesellschaften“ "
      "oder „Grundstücksverkehrsgenehmigungszuständigkeitsübertragungsverordnung“, die in Wörterbüchern fehlen.",
      "Er sagte: „Wir treffen uns am 3. Oktober um 14:00 Uhr vor dem Rathaus (Eingang B), bringt bitte 20 € mit!“",
      "Die E-Mail-Adresse, die Ein- und Ausgänge sowie die Haupt- und Nebenstraßen (vgl. S. 4–7, Nr. 12/13) "
      "wurden am 1.\u00a0Januar 2024 im Rahmen des Bund-Länder-Programms „Soziale Stadt“ neu geordnet.",
  };
  return t;
}

// Other scripts, each in a Noto face (fonts-noto-core, fonts-noto-cjk), with
// Noto Sans for the Latin letters and digits the Arabic and Hebrew faces lack.
constexpr const char* kNoto = "/usr/share/fonts/truetype/noto/";
struct ScriptSet {
  const char* name;
  std::vector<std::string> files;  // curvetext: first choice first
  const char* pango_family;        // Pango: families fontconfig resolves to the same files
  std::vector<std::string> texts;
};

const std::vector<ScriptSet>& script_sets() {
  static const std::vector<ScriptSet> sets = {
      {"Arabic (+Latin, digits)",
       {std::string(kNoto) + "NotoSansArabic-Regular.ttf", std::string(kNoto) + "NotoSans-Regular.ttf"},
       "Noto Sans Arabic, Noto Sans",
       {"في عام 2023 زار أكثر من 1,500,000 سائح مدينة البتراء في الأردن، وهي واحدة من عجائب الدنيا السبع الجديدة "
        "التي أعلنتها مؤسسة New7Wonders في 7 يوليو 2007.",
        "يستخدم نظام Linux في معظم خوادم الإنترنت، ويعمل عليه أيضاً نظام Android في الهواتف الذكية. يمكن تحميل "
        "الإصدار 6.1 من الموقع الرسمي kernel.org مجاناً.",
        "قال المدير إن الاجتماع سيعقد يوم الأحد الساعة 10:30 صباحاً في القاعة رقم 4، وسيناقش المشاركون الميزانية "
        "الجديدة البالغة 250 ألف دولار وخطة العمل للأشهر الستة القادمة.",
        "اللغة العربية هي إحدى اللغات الرسمية الست في الأمم المتحدة، ويتحدث بها أكثر من 400 مليون شخص حول العالم، "
        "وتكتب من اليمين إلى اليسار بأبجدية تتكون من 28 حرفاً."}},
      {"Hebrew",
       {std::string(kNoto) + "NotoSansHebrew-Regular.ttf", std::string(kNoto) + "NotoSans-Regular.ttf"},
       "Noto Sans Hebrew, Noto Sans",
       {"ירושלים היא בירת ישראל והעיר הגדולה ביותר במדינה, עם אוכלוסייה של כמעט מיליון תושבים. העיר העתיקה "
        "מוקפת חומה שנבנתה במאה השש עשרה.",
        "השפה העברית נכתבת מימין לשמאל באלפבית של עשרים ושתיים אותיות. במשך מאות שנים שימשה בעיקר לתפילה "
        "וללימוד, ובסוף המאה התשע עשרה חזרה להיות שפה מדוברת.",
        "הפגישה נדחתה ליום שלישי בשעה 14:00, כי רוב חברי הוועדה נמצאים בחופשה. נא להביא את המסמכים החתומים "
        "ואת הדוח השנתי של 2023."}},
      {"Devanagari",
       {std::string(kNoto) + "NotoSansDevanagari-Regular.ttf", std::string(kNoto) + "NotoSans-Regular.ttf"},
       "Noto Sans Devanagari, Noto Sans",
       {"भारत दक्षिण एशिया में स्थित एक विशाल देश है। जनसंख्या के हिसाब से यह दुनिया का सबसे बड़ा देश है और "
        "यहाँ सैकड़ों भाषाएँ बोली जाती हैं।",
        "हिन्दी देवनागरी लिपि में लिखी जाती है, जिसमें स्वर और व्यंजन के साथ मात्राएँ और संयुक्ताक्षर होते हैं, जैसे "
        "क्ष, त्र और ज्ञ।",
        "कल सुबह दस बजे विद्यालय में वार्षिक समारोह होगा, जिसमें विद्यार्थी नाटक, संगीत और नृत्य प्रस्तुत करेंगे तथा "
        "पुरस्कार वितरित किए जाएँगे।"}},
      {"Thai",
       {std::string(kNoto) + "NotoSansThai-Regular.ttf", std::string(kNoto) + "NotoSans-Regular.ttf"},
       "Noto Sans Thai, Noto Sans",
       {"ประเทศไทยตั้งอยู่ในเอเชียตะวันออกเฉียงใต้ มีกรุงเทพมหานครเป็นเมืองหลวงและเป็นเมืองที่ใหญ่ที่สุดของประเทศ",
        "ภาษาไทยเขียนโดยไม่เว้นวรรคระหว่างคำ แต่จะเว้นวรรคเมื่อจบประโยคหรือวลี ทำให้การตัดคำต้องใช้พจนานุกรม",
        "พรุ่งนี้เช้าเราจะไปตลาดน้ำเพื่อซื้อผลไม้และขนมไทย แล้วตอนบ่ายจะไปเที่ยววัดพระแก้วกับเพื่อนๆ"}},
      {"CJK (Chinese, Japanese)",
       {"/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc#2"},
       "Noto Sans CJK SC",
       {"北京是中华人民共和国的首都，也是全国的政治、文化和国际交往中心。这座城市有三千多年的建城史，故宫、天坛和长城都"
        "是世界文化遗产。",
        "汉字是世界上最古老的文字之一，现代汉语常用字大约有三千五百个。计算机排版时，每个汉字之间都可以换行，但标点符号"
        "不能出现在行首。",
        "東京は日本の首都であり、世界有数の大都市です。電車やバスなどの公共交通機関が発達していて、毎日何百万人もの人々"
        "が通勤しています。"}},
  };
  return sets;
}

// Line starts per script (--check-scripts): the sets above, plus scripts
// written without spaces between words. Thai gets libthai's dictionary
// breaks on both sides; Lao, Khmer and Myanmar have no dictionary on either
// side, so both break them at spaces, else between grapheme clusters.
const std::vector<ScriptSet>& unspaced_sets() {
  static const std::vector<ScriptSet> sets = {
      {"Thai without spaces",
       {std::string(kNoto) + "NotoSansThai-Regular.ttf", std::string(kNoto) + "NotoSans-Regular.ttf"},
       "Noto Sans Thai, Noto Sans",
       {"ภาษาไทยเขียนโดยไม่เว้นวรรคระหว่างคำการตัดคำจึงต้องใช้พจนานุกรมเพื่อหาว่าคำหนึ่งจบลงที่ใด",
        "ประเทศไทยตั้งอยู่ในเอเชียตะวันออกเฉียงใต้มีกรุงเทพมหานครเป็นเมืองหลวงและเป็นเมืองที่ใหญ่ที่สุดของประเทศ",
        "พรุ่งนี้เช้าเราจะไปตลาดน้ำเพื่อซื้อผลไม้และขนมไทยแล้วตอนบ่ายจะไปเที่ยววัดพระแก้วกับเพื่อน",
        "นักเรียนทุกคนต้องมาโรงเรียนก่อนแปดโมงเช้าเพื่อเข้าแถวเคารพธงชาติและร้องเพลงชาติพร้อมกัน"}},
      {"Lao",
       {std::string(kNoto) + "NotoSansLao-Regular.ttf"},
       "Noto Sans Lao",
       {"ພາສາລາວເປັນພາສາທາງການຂອງສາທາລະນະລັດປະຊາທິປະໄຕປະຊາຊົນລາວ ແລະ ຂຽນດ້ວຍອັກສອນລາວ"}},
      {"Khmer",
       {std::string(kNoto) + "NotoSansKhmer-Regular.ttf"},
       "Noto Sans Khmer",
       {"ភាសាខ្មែរគឺជាភាសាផ្លូវការរបស់ព្រះរាជាណាចក្រកម្ពុជា ហើយត្រូវបានសរសេរដោយអក្សរខ្មែរ"}},
      {"Myanmar",
       {std::string(kNoto) + "NotoSansMyanmar-Regular.ttf"},
       "Noto Sans Myanmar",
       {"မြန်မာဘာသာစကားသည်မြန်မာနိုင်ငံ၏ရုံးသုံးဘာသာစကားဖြစ်ပြီး မြန်မာအက္ခရာဖြင့်ရေးသားသည်"}},
  };
  return sets;
}

struct PangoSetup {
  PangoFontMap* map = pango_ft2_font_map_new();
  PangoContext* context = nullptr;
  PangoFontDescription* desc;
  explicit PangoSetup(const char* family = kFontFamily) : desc(pango_font_description_from_string(family)) {
    context = pango_font_map_create_context(map);
    // Unrounded positions, as curvetext keeps them.
    pango_context_set_round_glyph_positions(context, FALSE);
    pango_font_description_set_absolute_size(desc, kSize * PANGO_SCALE);
  }
  ~PangoSetup() {
    pango_font_description_free(desc);
    g_object_unref(context);
    g_object_unref(map);
  }
  // Font files (path#index) of the runs Pango laid out text with.
  std::set<std::string> font_files(const std::string& text) {
    PangoLayout* layout = make_layout(text, kWidth, true);
    std::set<std::string> files;
    PangoLayoutIter* iter = pango_layout_get_iter(layout);
    do {
      PangoLayoutRun* run = pango_layout_iter_get_run_readonly(iter);
      if (run == nullptr || !PANGO_IS_FC_FONT(run->item->analysis.font)) continue;
      FcPattern* pattern = pango_fc_font_get_pattern(PANGO_FC_FONT(run->item->analysis.font));
      FcChar8* file = nullptr;
      int index = 0;
      if (FcPatternGetString(pattern, FC_FILE, 0, &file) != FcResultMatch) continue;
      FcPatternGetInteger(pattern, FC_INDEX, 0, &index);
      files.insert(std::string(reinterpret_cast<const char*>(file)) + "#" + std::to_string(index));
    } while (pango_layout_iter_next_run(iter));
    pango_layout_iter_free(iter);
    g_object_unref(layout);
    return files;
  }
  PangoLayout* make_layout(const std::string& text, double width, bool hyphens) {
    PangoLayout* layout = pango_layout_new(context);
    if (!hyphens) {
      // Pango (>= 1.44) draws a hyphen where it breaks inside a word; off,
      // its emergency breaks follow the same rule as ours.
      PangoAttrList* attrs = pango_attr_list_new();
      pango_attr_list_insert(attrs, pango_attr_insert_hyphens_new(FALSE));
      pango_layout_set_attributes(layout, attrs);
      pango_attr_list_unref(attrs);
    }
    pango_layout_set_font_description(layout, desc);
    pango_layout_set_width(layout, static_cast<int>(width * PANGO_SCALE));
    pango_layout_set_wrap(layout, PANGO_WRAP_WORD_CHAR);
    pango_layout_set_text(layout, text.data(), static_cast<int>(text.size()));
    return layout;
  }
  std::vector<std::size_t> line_starts(const std::string& text, int* lines_out = nullptr, double width = kWidth,
                                       bool hyphens = true) {
    PangoLayout* layout = make_layout(text, width, hyphens);
    std::vector<std::size_t> starts;
    const int n = pango_layout_get_line_count(layout);
    if (lines_out) *lines_out = n;
    if (!lines_out)
      for (int i = 0; i < n; ++i)
        starts.push_back(static_cast<std::size_t>(pango_layout_get_line_readonly(layout, i)->start_index));
    g_object_unref(layout);
    return starts;
  }
};

curvetext::ParagraphStyle style(double width = kWidth, const std::vector<std::string>& fonts = {kFontFile}) {
  curvetext::ParagraphStyle s;
  s.default_style.fonts = fonts;
  s.default_style.size_px = kSize;
  s.width = width;
  return s;
}

std::vector<std::size_t> our_starts(curvetext::FontCollection& fonts, const std::string& text, double width) {
  std::vector<std::size_t> starts;
  const curvetext::Paragraph p = curvetext::Paragraph::layout(fonts, text, {}, style(width));
  for (const auto& l : p.lines()) starts.push_back(l.start);
  return starts;
}

// CPU time of this thread: the machine may be shared, and other processes'
// load should not count against either side.
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Paragraphs per CPU second of one round (at least 0.3 s) of lay_out over texts.
template <typename F>
double round_rate(const std::vector<std::string>& texts, F&& lay_out) {
  std::size_t count = 0;
  const double t0 = thread_seconds();
  double elapsed = 0;
  do {
    for (const std::string& t : texts) lay_out(t);
    count += texts.size();
    elapsed = thread_seconds() - t0;
  } while (elapsed < 0.3);
  return static_cast<double>(count) / elapsed;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
// Every paragraph at several widths (more line ends to compare than one
// width gives), against Pango with and without its inserted hyphens.
//  * Hyphens off: every line start must be Pango's.
//  * Hyphens on (Pango's default): differences are allowed only where Pango
//    breaks inside a word too long for the line (not a UAX #14 opportunity):
//    Pango then draws a hyphen and so breaks one character earlier, while
//    curvetext breaks such words without a hyphen (CSS overflow-wrap:
//    break-word). Each such difference is printed.
int check_breaks() {
  curvetext::FontCollection fonts;
  PangoSetup pango;
  int total = 0, breaks = 0, differ_plain = 0, differ_hyphen = 0, unexplained = 0;
  auto show = [](const std::string& text, const char* who, const std::vector<std::size_t>& s) {
    std::printf("  %s:", who);
    for (std::size_t k = 1; k < s.size(); ++k) {
      const std::size_t a = s[k] >= 12 ? s[k] - 12 : 0;
      std::printf(" [%zu]...%s|", s[k], text.substr(a, s[k] - a).c_str());
    }
    std::printf("\n");
  };
  for (const double width : {160.0, 240.0, 330.0, 420.0, 560.0})
    for (const auto* set : {&english(), &german()})
      for (const std::string& text : *set) {
        ++total;
        const auto ours = our_starts(fonts, text, width);
        const auto plain = pango.line_starts(text, nullptr, width, false);
        const auto hyphenated = pango.line_starts(text, nullptr, width, true);
        breaks += static_cast<int>(plain.size()) - 1;
        if (ours != plain) {
          ++differ_plain;
          std::printf("DIFFERS (Pango without hyphens) at width %.0f: \"%.40s...\"\n", width, text.c_str());
          show(text, "curvetext", ours);
          show(text, "pango    ", plain);
        }
        if (ours == hyphenated) continue;
        ++differ_hyphen;
        // The first line start that differs must be a break inside a word.
        std::size_t k = 0;
        while (k < ours.size() && k < hyphenated.size() && ours[k] == hyphenated[k]) ++k;
        bool inside_word = false;
        if (k < hyphenated.size()) {
          gchar* head = g_strndup(text.data(), hyphenated[k]);
          glong n = 0;
          gunichar* cps = g_utf8_to_ucs4_fast(text.c_str(), -1, &n);
          const std::size_t at = static_cast<std::size_t>(g_utf8_strlen(head, -1));
          const std::vector<curvetext::BreakAction> opportunities = curvetext::line_breaks(
              std::u32string(reinterpret_cast<const char32_t*>(cps), static_cast<std::size_t>(n)));
          inside_word = at > 0 && opportunities[at - 1] == curvetext::BreakAction::None;
          g_free(cps);
          g_free(head);
        }
        if (!inside_word) ++unexplained;
        std::printf("%s (Pango's default, hyphen at a break inside a word) at width %.0f: \"%.40s...\"\n",
                    inside_word ? "differs" : "DIFFERS, NOT EXPLAINED", width, text.c_str());
        show(text, "curvetext", ours);
        show(text, "pango    ", hyphenated);
      }
  std::printf("line breaks (widths 160, 240, 330, 420, 560 px; %d Pango line breaks):\n", breaks);
  std::printf("  %d of %d paragraph layouts identical to Pango's with insert-hyphens off\n", total - differ_plain,
              total);
  std::printf(
      "  %d of %d identical to Pango's default (insert-hyphens on); %d differ only where Pango hyphenates "
      "a word longer than the line, %d unexplained\n",
      total - differ_hyphen, total, differ_hyphen - unexplained, unexplained);
  return differ_plain == 0 && unexplained == 0 ? 0 : 1;
}

// Per script: line starts against Pango's (insert-hyphens off) at several
// widths, and whether both drew with the same font files, as a Markdown
// table; each layout that differs is printed.
int check_scripts() {
  curvetext::FontCollection fonts;
  std::vector<ScriptSet> sets = {{"Latin (English, German)", {kFontFile}, kFontFamily, english()}};
  sets.back().texts.insert(sets.back().texts.end(), german().begin(), german().end());
  for (const auto* group : {&script_sets(), &unspaced_sets()}) sets.insert(sets.end(), group->begin(), group->end());
  const std::vector<double> widths = {120.0, 160.0, 240.0, 330.0, 420.0};
  std::string table =
      "| script | font files | paragraphs | layouts identical | line starts identical |\n|---|---|---|---|---|\n";
  int all_differ = 0;
  for (const ScriptSet& set : sets) {
    PangoSetup pango(set.pango_family);
    int layouts = 0, same_layouts = 0, starts = 0, same_starts = 0;
    std::set<std::string> ours_files, pango_files;
    for (const double width : widths)
      for (const std::string& text : set.texts) {
        std::vector<std::size_t> ours;
        const curvetext::Paragraph p = curvetext::Paragraph::layout(fonts, text, {}, style(width, set.files));
        for (const auto& l : p.lines()) {
          ours.push_back(l.start);
          for (const auto& run : l.runs)
            ours_files.insert(run.font->path() + "#" + std::to_string(run.font->face_index()));
        }
        const auto f = pango.font_files(text);
        pango_files.insert(f.begin(), f.end());
        const auto theirs = pango.line_starts(text, nullptr, width, false);
        ++layouts;
        same_layouts += ours == theirs ? 1 : 0;
        for (std::size_t k = 1; k < theirs.size(); ++k, ++starts)
          same_starts += std::find(ours.begin(), ours.end(), theirs[k]) != ours.end() ? 1 : 0;
        if (ours == theirs) continue;
        ++all_differ;
        std::printf("%s differs at width %.0f: \"%.60s...\"\n", set.name, width, text.c_str());
        std::printf("  curvetext:");
        for (std::size_t k = 1; k < ours.size(); ++k) std::printf(" %zu", ours[k]);
        std::printf("\n  pango    :");
        for (std::size_t k = 1; k < theirs.size(); ++k) std::printf(" %zu", theirs[k]);
        std::printf("\n");
      }
    char row[256];
    const bool same_files = ours_files == pango_files;
    all_differ += same_files ? 0 : 1;
    std::snprintf(row, sizeof row, "| %s | %s | %zu | %d of %d | %d of %d |\n", set.name,
                  same_files ? "identical" : "DIFFER", set.texts.size(), same_layouts, layouts, same_starts, starts);
    table += row;
  }
  std::printf("\nline starts against Pango 1.50 (insert-hyphens off), %.0f px, widths 120, 160, 240, 330, 420 px:\n%s",
              kSize, table.c_str());
  return all_differ == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--check-breaks") == 0) return check_breaks();
  if (argc > 1 && std::strcmp(argv[1], "--check-scripts") == 0) return check_scripts();
  std::vector<std::string> texts = english();
  texts.insert(texts.end(), german().begin(), german().end());
  curvetext::FontCollection fonts;
  PangoSetup pango;
  std::size_t sink = 0;
  // --profile N: N rounds of curvetext only (for callgrind / perf).
  if (argc > 2 && std::strcmp(argv[1], "--profile") == 0) {
    for (int k = std::atoi(argv[2]); k > 0; --k)
      for (const std::string& t : texts) sink += curvetext::Paragraph::layout(fonts, t, {}, style()).lines().size();
    std::printf("[%zu]\n", sink);
    return 0;
  }
  // Rounds alternate between the two so that a change in machine load hits
  // both alike; each figure is the median of 7 rounds.
  const auto measure = [&](const std::vector<std::string>& set, const std::vector<std::string>& files,
                           PangoSetup& with) {
    std::vector<double> ours, theirs;
    for (int round = 0; round < 7; ++round) {
      ours.push_back(round_rate(set, [&](const std::string& t) {
        sink += curvetext::Paragraph::layout(fonts, t, {}, style(kWidth, files)).lines().size();
      }));
      theirs.push_back(round_rate(set, [&](const std::string& t) {
        int n = 0;
        with.line_starts(t, &n);
        sink += static_cast<std::size_t>(n);
      }));
    }
    return std::pair{median(ours), median(theirs)};
  };
  const auto [a, b] = measure(texts, {kFontFile}, pango);
  std::printf("layout of %zu paragraphs (%s %.0f px, width %.0f px), per CPU second, median of 7 alternating rounds\n",
              texts.size(), kFontFile, kSize, kWidth);
  std::printf("  curvetext: %10.0f paragraphs/s\n", a);
  std::printf("  pango    : %10.0f paragraphs/s (pangoft2)\n", b);
  std::printf("  ratio    : %.2fx (target >= 2x)   [%zu]\n", a / b, sink % 10);

  // Other scripts: the same method, one table row per script, after a check
  // that both sides draw with the same font files and a count of their lines.
  struct Row {
    std::string name;
    std::size_t paragraphs;
    int lines_ours, lines_pango;
    double ours, pango;
  };
  std::vector<Row> rows;
  bool all_same_files = true;
  std::printf("\nother scripts (%.0f px, width %.0f px):\n", kSize, kWidth);
  for (const ScriptSet& set : script_sets()) {
    PangoSetup with(set.pango_family);
    std::set<std::string> ours_files, pango_files;
    int lines_ours = 0, lines_pango = 0;
    for (const std::string& t : set.texts) {
      const curvetext::Paragraph p = curvetext::Paragraph::layout(fonts, t, {}, style(kWidth, set.files));
      lines_ours += static_cast<int>(p.lines().size());
      for (const auto& line : p.lines())
        for (const auto& run : line.runs)
          ours_files.insert(run.font->path() + "#" + std::to_string(run.font->face_index()));
      int n = 0;
      with.line_starts(t, &n);
      lines_pango += n;
      const auto f = with.font_files(t);
      pango_files.insert(f.begin(), f.end());
    }
    const bool same = ours_files == pango_files;
    all_same_files = all_same_files && same;
    std::printf("  %-24s font files %s:", set.name, same ? "identical" : "DIFFER");
    for (const auto& f : ours_files) std::printf(" %s", f.c_str());
    if (!same) {
      std::printf("  | Pango:");
      for (const auto& f : pango_files) std::printf(" %s", f.c_str());
    }
    std::printf("\n");
    const auto [x, y] = measure(set.texts, set.files, with);
    rows.push_back({set.name, set.texts.size(), lines_ours, lines_pango, x, y});
  }
  std::printf(
      "\n| script | paragraphs | lines curvetext / Pango | curvetext paragraphs/s | Pango paragraphs/s | ratio |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::printf("| Latin (English, German; DejaVu Sans) | %zu | | %.0f | %.0f | %.2fx |\n", texts.size(), a, b, a / b);
  for (const Row& r : rows)
    std::printf("| %s | %zu | %d / %d | %.0f | %.0f | %.2fx |\n", r.name.c_str(), r.paragraphs, r.lines_ours,
                r.lines_pango, r.ours, r.pango, r.ours / r.pango);
  std::printf("[%zu]\n", sink % 10);
  return all_same_files ? 0 : 1;
}
