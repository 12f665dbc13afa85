// lwb-i18n-strings: the parameter schemas' texts (each row's label, doc and special values'
// meanings) as a C++ source lupdate reads, so that the one row of a parameter is also what its
// translation is made from (and the key sections the panels head their rows with). `make translations` runs it into ui/i18n/schema_strings.cpp and then
// lupdate; ui_test_translations fails when a row's text has no translation.
//   lwb-i18n-strings OUT.cpp
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "core/calib/calib_params.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/footprint/trend.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/slr/slr_params.hpp"

namespace {
std::string cLiteral(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') { out += "\\n"; continue; }
        out += c;
    }
    return out + "\"";
}

template <class P>
void collect(const lwb::core::Schema<P>& schema, std::vector<std::string>* out, std::set<std::string>* seen) {
    for (const auto& f : schema.fields()) {
        std::vector<std::string> texts = {f.label(), f.doc};
        // The section of the key ("gauss" of "gauss.lm_tolerance_px"): the panels' headings.
        if (const size_t dot = f.key.rfind('.'); dot != std::string::npos) texts.push_back(f.key.substr(0, dot));
        for (const auto& s : f.specials) texts.push_back(s.meaning);
        for (const std::string& t : texts)
            if (!t.empty() && seen->insert(t).second) out->push_back(t);
    }
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: lwb-i18n-strings OUT.cpp\n");
        return 2;
    }
    std::vector<std::string> texts;
    std::set<std::string> seen;
    collect(lwb::core::footprint::footprintSchema(), &texts, &seen);
    collect(lwb::core::footprint::trendSchema(), &texts, &seen);
    collect(lwb::core::slr::slrSchema(), &texts, &seen);
    collect(lwb::core::calib::calibSchema(), &texts, &seen);
    collect(lwb::core::radiometry::radiometrySchema(), &texts, &seen);
    std::ofstream f(argv[1], std::ios::binary);
    f << "// Written by lwb-i18n-strings (app/i18n_strings.cpp; `make translations`): the texts of the\n"
         "// parameter schemas' rows, for lupdate. Do not edit: edit the rows and run make translations.\n"
         "#include <QtGlobal>\n\n"
         "namespace lwb::ui {\n"
         "[[maybe_unused]] const char* const kSchemaTexts[] = {\n";
    for (const std::string& t : texts) f << "    QT_TRANSLATE_NOOP(\"schema\", " << cLiteral(t) << "),\n";
    f << "};\n}  // namespace lwb::ui\n";
    if (!f) {
        fprintf(stderr, "lwb-i18n-strings: cannot write %s\n", argv[1]);
        return 1;
    }
    printf("lwb-i18n-strings: %zu texts in %s\n", texts.size(), argv[1]);
    return 0;
}
