#include "cli_common.hpp"

#include <cstdio>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

#include "core/common/text.hpp"

namespace lwb::cli {

void Args::option(const std::string& name, bool takesValue, bool repeatable) {
    m_spec[name] = {takesValue, repeatable};
}

bool Args::parse(int argc, char** argv, int first) {
    bool onlyPositional = false;
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (onlyPositional || a.size() < 2 || a[0] != '-' || a == "-") {
            m_positional.push_back(a);
            continue;
        }
        if (a == "--") {
            onlyPositional = true;
            continue;
        }
        std::string name = a, value;
        bool inlineValue = false;
        if (a.rfind("--", 0) == 0) {
            if (const size_t eq = a.find('='); eq != std::string::npos) {
                name = a.substr(0, eq);
                value = a.substr(eq + 1);
                inlineValue = true;
            }
        }
        const auto it = m_spec.find(name);
        if (it == m_spec.end()) {
            std::vector<std::string> names{"--version"};  // (answered before any command's parser)
            for (const auto& [n, spec] : m_spec) names.push_back(n);
            m_error = "unknown option " + name + core::didYouMean(name, names);
            return false;
        }
        if (it->second.first) {
            if (!inlineValue) {
                if (i + 1 >= argc) {
                    m_error = name + " needs a value";
                    return false;
                }
                value = argv[++i];
            }
        } else if (inlineValue) {
            m_error = name + " takes no value";
            return false;
        }
        if (!it->second.second && m_values.count(name)) {
            m_error = name + " given twice";
            return false;
        }
        m_values.emplace(name, value);
    }
    return true;
}

int Args::parseWithHelp(int argc, char** argv, int first) {
    for (const char* o : {"--help", "-h", "-q", "--quiet"}) option(o, false);
    if (!parse(argc, argv, first)) return fail(m_command, m_error, kUsage);
    if (has("--help") || has("-h")) {
        std::cout << m_usage;
        return kOk;
    }
    return -1;
}

std::string Args::value(const std::string& name, const std::string& fallback) const {
    const auto it = m_values.find(name);
    return it == m_values.end() ? fallback : it->second;
}

std::vector<std::string> Args::values(const std::string& name) const {
    std::vector<std::string> out;
    const auto range = m_values.equal_range(name);
    for (auto it = range.first; it != range.second; ++it) out.push_back(it->second);
    return out;
}

bool Args::getInt(const std::string& name, long long lo, long long hi, long long* out, std::string* err) const {
    if (!has(name)) return true;
    long long v = 0;
    if (!core::parseLong(value(name), &v) || v < lo || v > hi) {
        *err = name + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", not \"" +
               value(name) + "\"";
        return false;
    }
    *out = v;
    return true;
}

bool Args::getDouble(const std::string& name, double lo, double hi, double* out, std::string* err) const {
    if (!has(name)) return true;
    double v = 0;
    if (!core::parseDouble(value(name), &v) || v < lo || v > hi) {
        *err = name + " must be a number from " + core::formatDouble(lo, 6) + " to " + core::formatDouble(hi, 6) +
               ", not \"" + value(name) + "\"";
        return false;
    }
    *out = v;
    return true;
}

namespace {
std::string g_lastFailure;
}

const std::string& lastFailure() { return g_lastFailure; }

void warnings(const std::string& command, const std::vector<std::string>& ws, bool quiet, bool doubtful) {
    if (quiet && !doubtful) return;
    for (const auto& w : ws) std::cerr << "laserwb-cli " << command << ": warning: " << w << "\n";
}

int fail(const std::string& command, const std::string& message, int code) {
    g_lastFailure = message;
    std::cerr << "laserwb-cli " << command << ": " << message << "\n";
    if (code == kUsage) std::cerr << "Run 'laserwb-cli " << command << " --help' for usage.\n";
    return code;
}

Progress::Progress(std::string what, size_t total, bool quiet)
    : m_what(std::move(what)), m_total(total), m_quiet(quiet || total < 50), m_tty(::isatty(2)) {
    m_start = m_last = std::chrono::steady_clock::now();
}

void Progress::update(size_t done) {
    if (m_quiet || m_total == 0) return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const double rate = elapsed > 0 ? done / elapsed : 0;
    const double eta = rate > 0 ? (m_total - done) / rate : 0;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s %zu/%zu (%.0f%%), %.0f/s, %.0f s left", m_what.c_str(), done, m_total,
                  100.0 * done / m_total, rate, eta);
    if (m_tty) {
        if (std::chrono::duration<double>(now - m_last).count() < 0.2 && done < m_total) return;
        m_last = now;
        std::fprintf(stderr, "\r%s\033[K", buf);
    } else {
        const int decile = static_cast<int>(10 * done / m_total);
        if (decile == m_lastDecile) return;
        m_lastDecile = decile;
        std::fprintf(stderr, "%s\n", buf);
    }
}

void Progress::finish() {
    if (!m_quiet && m_tty) std::fprintf(stderr, "\n");
}

int checkOutputs(const std::string& command, core::OutputSet& outs) {
    if (!outs.check()) return fail(command, outs.error(), outs.namingProblem() ? kUsage : kFailed);
    // An output to standard output ("-o -"): the data alone goes there; everything the command
    // would print on standard output (its summary) goes to standard error instead.
    static bool moved = false;
    if (outs.writesStandardOutput() && !moved) {
        std::cout.flush();
        std::fflush(stdout);
        const int data = ::dup(1);
        if (data < 0 || ::dup2(2, 1) < 0) return fail(command, "cannot set standard output aside for the data");
        core::setStandardOutputFd(data);
        moved = true;
    }
    return kOk;
}

int commitOutputs(const std::string& command, core::OutputSet& outs) {
    return outs.commit() ? kOk : fail(command, outs.error(), outs.namingProblem() ? kUsage : kFailed);
}

bool parsePoint(const std::string& s, double* x, double* y) {
    const size_t c = s.find(',');
    return c != std::string::npos && core::parseDouble(s.substr(0, c), x) && core::parseDouble(s.substr(c + 1), y);
}

bool parseSize(const std::string& s, int* w, int* h) {
    const size_t c = s.find_first_of("xX");
    long long a = 0, b = 0;
    if (c == std::string::npos || !core::parseLong(s.substr(0, c), &a) || !core::parseLong(s.substr(c + 1), &b))
        return false;
    if (a < 1 || b < 1 || a > 65536 || b > 65536) return false;
    *w = static_cast<int>(a);
    *h = static_cast<int>(b);
    return true;
}

}  // namespace lwb::cli
