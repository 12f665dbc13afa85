#pragma once
// Shared by the parameter targets (fuzz_footprint_config, fuzz_slr_config): what the CLI does
// with a command's parameter schema (core/common/schema.hpp) in ParamOptions::apply
// (app/cli_common.hpp), the GUI's presets and the presets files.
// - An input starting with '{' is a --config file: parsed (core::parseJson) and read over the
//   defaults with its member positions, as the CLI reads it.
// - Anything else is one --set KEY=VALUE (the first '=' splits it).
// Either is applied or refused with a reason. Parameters that were applied validate, are written
// (toJson) and read again to the same document, and every field's text (valueText, as the
// tables show it) set back through --set gives the same document. Written with core::dumpJson,
// as the CLI writes --print-config.
#include <string>
#include <string_view>
#include <vector>

#include "core/common/json.hpp"
#include "core/common/schema.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace lwb::fuzz {

/// `fromJson(parsed, &params, &error)`: how the command reads a --config file.
template <class P, class FromJson>
void fuzzParams(const core::Schema<P>& schema, std::string_view bytes, FromJson fromJson) {
    P p{};
    std::string err;
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && bytes[first] == '{') {
        const core::JsonParseResult j = core::parseJson(std::string(bytes), "fuzz");
        checkReported(j.ok, j.error);
        if (!j.ok) return;
        const bool ok = fromJson(j, &p, &err);
        checkReported(ok, err);
        if (!ok) return;
    } else {
        const size_t eq = bytes.find('=');
        if (eq == std::string_view::npos) return;
        const bool ok = schema.setFromText(&p, std::string(bytes.substr(0, eq)), std::string(bytes.substr(eq + 1)), &err);
        checkReported(ok, err);
        if (!ok) return;
    }
    check(schema.validate(p).empty());
    const std::string text = core::dumpJson(schema.toJson(p), -1);
    const core::JsonParseResult back = core::parseJson(text, "fuzz");
    check(back.ok);
    P q{};
    check(fromJson(back, &q, &err));
    check(core::dumpJson(schema.toJson(q), -1) == text);
    // Field by field as --set does; a rule between two fields may refuse one until the other is
    // set, so refused fields are tried again while any pass makes progress.
    P r{};
    std::vector<const typename core::Schema<P>::Field*> left;
    for (const auto& f : schema.fields()) left.push_back(&f);
    for (size_t before = left.size() + 1; !left.empty() && left.size() < before;) {
        before = left.size();
        std::vector<const typename core::Schema<P>::Field*> refused;
        for (const auto* f : left)
            if (!schema.setFromText(&r, f->key, schema.valueText(*f, p), &err)) refused.push_back(f);
        left = refused;
    }
    check(left.empty());
    check(core::dumpJson(schema.toJson(r), -1) == text);
}

/// A target for a schema whose --config is read by Schema::fromJson itself (slr, calib,
/// radiometry, trend): the whole LLVMFuzzerTestOneInput body.
template <class P>
int fuzzSchemaConfig(const core::Schema<P>& schema, const uint8_t* data, size_t size) {
    fuzzParams(schema, asText(data, size), [&schema](const core::JsonParseResult& j, P* p, std::string* err) {
        return schema.fromJson(j.value, p, err, &j);
    });
    return 0;
}

}  // namespace lwb::fuzz
