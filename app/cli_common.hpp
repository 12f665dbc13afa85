#pragma once
// Shared plumbing of laserwb-cli: option parsing, messages, progress on stderr.
#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "core/common/output_set.hpp"
#include "core/common/schema.hpp"

namespace lwb::cli {

/// Exit codes, kept by every command (README, "Command line"): 0 success; 1 bad input or failed
/// run (nothing written); 2 usage error; 3 the outputs are written, but a result is doubtful or
/// incomplete (the reasons on stderr, even with -q, and in the outputs); 4 (slr --all-passes)
/// the outputs are written, but some passes failed (summary.csv says why).
enum Exit { kOk = 0, kFailed = 1, kUsage = 2, kDoubtful = 3, kSomeFailed = 4 };

/// A small option parser: "--name value", "--name=value", flags, repeatable options, and
/// positional arguments; unknown options are errors.
class Args {
public:
    Args(std::string command, std::string usage) : m_command(std::move(command)), m_usage(std::move(usage)) {}
    void option(const std::string& name, bool takesValue, bool repeatable = false);
    /// Parses argv[first..]; false with error() on an unknown option or a missing value.
    bool parse(int argc, char** argv, int first);
    /// Declares --help, -h, -q and --quiet, parses argv[first..] and answers --help with the
    /// usage: -1 to go on, else the exit code (after printing the usage or the parse error).
    int parseWithHelp(int argc, char** argv, int first);
    bool quiet() const { return has("-q") || has("--quiet"); }
    const std::string& error() const { return m_error; }
    const std::string& usage() const { return m_usage; }
    void setUsage(std::string usage) { m_usage = std::move(usage); }

    bool has(const std::string& name) const { return m_values.count(name) > 0; }
    std::string value(const std::string& name, const std::string& fallback = "") const;
    std::vector<std::string> values(const std::string& name) const;
    const std::vector<std::string>& positional() const { return m_positional; }

    /// Typed getters; false with *err ("--name: ...") when present but malformed or out of range.
    bool getInt(const std::string& name, long long lo, long long hi, long long* out, std::string* err) const;
    bool getDouble(const std::string& name, double lo, double hi, double* out, std::string* err) const;

private:
    std::string m_command, m_usage, m_error;
    std::map<std::string, std::pair<bool, bool>> m_spec;  // name → (takesValue, repeatable)
    std::multimap<std::string, std::string> m_values;
    std::vector<std::string> m_positional;
};

/// A run's warnings on stderr ("laserwb-cli COMMAND: warning: ..."); -q (`quiet`) silences them
/// when the run is sound, never when they explain a doubtful result (exit 3: `doubtful`).
void warnings(const std::string& command, const std::vector<std::string>& ws, bool quiet, bool doubtful = false);

/// Prints "laserwb-cli COMMAND: message" on stderr and returns code.
int fail(const std::string& command, const std::string& message, int code = kFailed);
/// The message of the last fail() (run summaries say why a run failed).
const std::string& lastFailure();

/// Throttled progress on stderr: a rewritten line on a terminal, a line per 10 % otherwise.
class Progress {
public:
    Progress(std::string what, size_t total, bool quiet);
    void update(size_t done);
    void finish();

private:
    std::string m_what;
    size_t m_total;
    bool m_quiet, m_tty;
    int m_lastDecile = -1;
    std::chrono::steady_clock::time_point m_start, m_last;
};

/// Checks a run's outputs before any work is done (core::OutputSet::check). 0 when they may be
/// written; else prints why and returns the exit code: usage (2) for outputs naming an input or
/// each other, failed (1) for a file-system problem.
int checkOutputs(const std::string& command, core::OutputSet& outs);
/// Renames a run's staged outputs into place: kOk, or prints why and returns kFailed (then none
/// of the outputs was replaced).
int commitOutputs(const std::string& command, core::OutputSet& outs);

/// An output folder that is removed again when the run fails (core/common/output_set.hpp).
using core::FolderForOutputs;

/// A named option that sets one schema field ("--cos-c" for "screen.cosine_c"): today's flags,
/// kept as aliases of --set.
struct ParamAlias {
    std::string flag, key;
};

/// --config FILE, --print-config and --set KEY=VALUE for a command whose parameters a schema
/// declares (core/common/schema.hpp), plus its named aliases. Ranges, messages and the JSON all
/// come from the schema, so the CLI, configs, presets and the GUI agree.
template <class P>
class ParamOptions {
public:
    ParamOptions(const core::Schema<P>& schema, std::vector<ParamAlias> aliases = {})
        : m_schema(schema), m_aliases(std::move(aliases)) {}

    /// Also fills the usage's "{default:KEY}" from the schema (Schema::fillDefaults).
    void declare(Args& a) const {
        a.setUsage(m_schema.fillDefaults(a.usage(), P{}));
        a.option("--config", true);
        a.option("--set", true, true);
        a.option("--print-config", false);
        for (const auto& al : m_aliases) a.option(al.flag, true);
    }
    /// Applies --config, then `afterConfig` (a command's own option that sets several fields,
    /// such as a preset), then the aliases, then each --set, over *p. 0 when fine, else the exit
    /// code after printing why: 1 for a bad config file, 2 for a bad option.
    int apply(const std::string& cmd, const Args& a, P* p, const std::function<int(P*)>& afterConfig = {}) const {
        std::string err;
        if (a.has("--config")) {
            const core::JsonParseResult j = core::readJsonFile(a.value("--config"));
            if (!j.ok) return fail(cmd, j.error);
            if (!fromJson(j, p, &err)) return fail(cmd, err);
        }
        if (afterConfig)
            if (int rc = afterConfig(p)) return rc;
        for (const auto& al : m_aliases)
            if (a.has(al.flag) && !m_schema.setFromText(p, al.key, a.value(al.flag), &err))
                return fail(cmd, al.flag + " " + a.value(al.flag) + ": " + err, kUsage);
        for (const std::string& kv : a.values("--set")) {
            const size_t eq = kv.find('=');
            if (eq == std::string::npos) return fail(cmd, "--set needs KEY=VALUE, not \"" + kv + "\"", kUsage);
            if (!m_schema.setFromText(p, std::string(core::trim(kv.substr(0, eq))), kv.substr(eq + 1), &err))
                return fail(cmd, "--set " + kv + ": " + err, kUsage);
        }
        return kOk;
    }
    bool printRequested(const Args& a) const { return a.has("--print-config"); }
    /// The named aliases, then each --set, as settings for the core to apply in that order (what
    /// apply() does itself, for a task that resolves its parameters in core). False with *error
    /// (a usage error) for a --set without '='.
    bool settings(const Args& a, std::vector<core::ParamSetting>* out, std::string* error) const {
        for (const auto& al : m_aliases)
            if (a.has(al.flag)) out->push_back({al.key, a.value(al.flag), al.flag + " " + a.value(al.flag)});
        for (const std::string& kv : a.values("--set")) {
            const size_t eq = kv.find('=');
            if (eq == std::string::npos) {
                *error = "--set needs KEY=VALUE, not \"" + kv + "\"";
                return false;
            }
            out->push_back({std::string(core::trim(kv.substr(0, eq))), kv.substr(eq + 1), "--set " + kv});
        }
        return true;
    }

    /// The usage's paragraph about these options (`what`: "calib", `example`: "detector.trigger=5").
    static std::string paramsHelp(const std::string& what, const std::string& example) {
        return "Parameters (every one: --print-config; units, ranges and meaning: --help-params):\n"
               "  --config FILE.json   parameters (the " + what + " block of a workbench session); options override it\n"
               "  --set KEY=VALUE      set one parameter (repeatable), e.g. --set " + example + "\n"
               "  --print-config       print the effective parameters as JSON and exit\n"
               "  --help-params        every parameter with its unit, range, default and meaning\n"
               "  -q, --quiet          no summary, progress or warnings on stderr (errors still)\n";
    }
    /// Declares these options with --help, -h, -q, --quiet and --help-params, parses argv[first..]
    /// and answers --help (the usage) and --help-params (the table). -1 to go on, else the exit code.
    int parseWithHelp(Args& a, int argc, char** argv, int first) const {
        declare(a);
        a.option("--help-params", false);
        if (int rc = a.parseWithHelp(argc, argv, first); rc >= 0) return rc;
        if (a.has("--help-params")) {
            std::cout << m_schema.name() << " parameters (key = default unit  valid range):\n" << m_schema.describe(P{});
            return kOk;
        }
        return -1;
    }
    /// apply() over *p, then `check` on the whole struct (rules between fields, checked once every
    /// setting is applied so the order of --set does not matter), then --print-config.
    /// -1 to go on, else the exit code.
    int load(const std::string& cmd, const Args& a, P* p, const std::function<std::string(const P&)>& check,
             const std::function<int(P*)>& afterConfig = {}) const {
        if (int rc = apply(cmd, a, p, afterConfig)) return rc;
        if (const std::string e = check(*p); !e.empty()) return fail(cmd, e, kUsage);
        if (printRequested(a)) {
            std::cout << json(*p);
            return kOk;
        }
        return -1;
    }
    std::string json(const P& p) const { return core::dumpJson(m_schema.toJson(p)); }

    /// How a config file is read: the schema's fromJson, or a caller's (a preset applied first).
    std::function<bool(const core::JsonParseResult&, P*, std::string*)> fromJson =
        [this](const core::JsonParseResult& j, P* p, std::string* err) { return m_schema.fromJson(j.value, p, err, &j); };

private:
    const core::Schema<P>& m_schema;
    std::vector<ParamAlias> m_aliases;
};

/// "X,Y" → two finite numbers.
bool parsePoint(const std::string& s, double* x, double* y);
/// "WxH" → two positive integers.
bool parseSize(const std::string& s, int* w, int* h);

}  // namespace lwb::cli
