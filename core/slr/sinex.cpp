#include "core/slr/sinex.hpp"

#include <functional>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/slr/slr_time.hpp"

namespace lwb::core::slr {

namespace {

std::string column(std::string_view line, size_t from, size_t len) {
    if (from >= line.size()) return {};
    return std::string(trim(line.substr(from, len)));
}

/// Validity of one SOLUTION/EPOCHS line.
struct Validity {
    double from = NAN, to = NAN;
};

}  // namespace

namespace {

using Warn = std::function<void(std::string)>;

// SITE/ID: code, point, DOMES, description, and the CDP SOD when the line ends with one.
void parseSiteLine(std::string_view line, long lineNo, const std::string& src, const Warn& warn, SinexFile& file) {
    const auto f = splitBlanks(line);
    if (f.size() < 3) {
        warn(whereInFile(src, lineNo) + "SITE/ID line too short; ignored");
        return;
    }
    SinexSite s;
    s.code = std::string(f[0]);
    s.point = std::string(f[1]);
    s.domes = f.size() > 2 ? std::string(f[2]) : std::string();
    s.description = column(line, 21, 22);
    const std::string_view last = f.back();
    if (f.size() > 8 && last.size() == 8 &&
        std::all_of(last.begin(), last.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
        s.cdpSod = std::string(last);
    s.line = lineNo;
    file.sites.push_back(std::move(s));
}

// SOLUTION/EPOCHS: a solution's validity interval (an end of 00:000:00000 is open).
void parseEpochsLine(std::string_view line, long lineNo, const std::string& src, const Warn& warn,
                     std::map<std::string, Validity>& validity) {
    const auto f = splitBlanks(line);
    long m1 = 0, m2 = 0;
    double s1 = 0, s2 = 0;
    if (f.size() < 6 || !parseSinexEpoch(f[4], &m1, &s1) || !parseSinexEpoch(f[5], &m2, &s2)) {
        warn(whereInFile(src, lineNo) + "SOLUTION/EPOCHS line unreadable; ignored");
        return;
    }
    Validity v;
    v.from = static_cast<double>(m1) + s1 / kSecondsPerDay;
    v.to = f[5] == "00:000:00000" ? INFINITY : static_cast<double>(m2) + s2 / kSecondsPerDay;
    validity[std::string(f[0]) + "|" + std::string(f[1]) + "|" + std::string(f[2])] = v;
}

// SOLUTION/ESTIMATE: STAX/STAY/STAZ and VELX/VELY/VELZ of a site's solution (other types ignored).
void parseEstimateLine(std::string_view line, long lineNo, const std::string& src, const Warn& warn,
                       std::map<std::string, size_t>& solIndex, SinexFile& file) {
    const auto f = splitBlanks(line);
    // INDEX TYPE CODE PT SOLN REF_EPOCH UNIT S VALUE STD
    if (f.size() < 9) {
        warn(whereInFile(src, lineNo) + "SOLUTION/ESTIMATE line has " + std::to_string(f.size()) +
             " fields (expected 10); ignored");
        return;
    }
    const std::string type(f[1]);
    static const char* kTypes[6] = {"STAX", "STAY", "STAZ", "VELX", "VELY", "VELZ"};
    int which = -1;
    for (int i = 0; i < 6; ++i)
        if (type == kTypes[i]) which = i;
    if (which < 0) return;
    long mjd = 0;
    double sod = 0, value = 0, sigma = NAN;
    if (!parseSinexEpoch(f[5], &mjd, &sod)) {
        warn(whereInFile(src, lineNo) + "REF_EPOCH \"" + printableExcerpt(f[5]) + "\" is not YY:DOY:SSSSS; ignored");
        return;
    }
    if (!parseFortranDouble(f[8], &value)) {
        warn(whereInFile(src, lineNo) + "estimated value \"" + printableExcerpt(f[8]) + "\" is not a finite number; ignored");
        return;
    }
    if (f.size() > 9 && !parseFortranDouble(f[9], &sigma)) sigma = NAN;
    const std::string unit(f[6]);
    if ((which < 3 && unit != "m") || (which >= 3 && unit != "m/y")) {
        warn(whereInFile(src, lineNo) + type + " unit \"" + printableExcerpt(unit) + "\" (expected " +
             (which < 3 ? "m" : "m/y") + "); ignored");
        return;
    }
    if (which < 3 && std::fabs(value) > 1e8) {
        warn(whereInFile(src, lineNo) + type + " beyond 1e8 m; ignored");
        return;
    }
    const std::string key = std::string(f[2]) + "|" + std::string(f[3]) + "|" + std::string(f[4]);
    auto it = solIndex.find(key);
    if (it == solIndex.end()) {
        SinexSolution s;
        s.code = std::string(f[2]);
        s.point = std::string(f[3]);
        s.soln = std::string(f[4]);
        s.refMjd = mjd;
        s.refSod = sod;
        s.line = lineNo;
        file.solutions.push_back(s);
        it = solIndex.emplace(key, file.solutions.size() - 1).first;
    }
    SinexSolution& s = file.solutions[it->second];
    if (which >= 3 && (s.haveMask & 0x38) == 0 && (s.haveMask & 7) != 0 && (mjd != s.refMjd || sod != s.refSod))
        warn(whereInFile(src, lineNo) + "velocity REF_EPOCH differs from the position's; the position's is used");
    if (s.haveMask & (1 << which)) warn(whereInFile(src, lineNo) + "second " + type + " for " + s.code + "; replaces the first");
    if (which < 3) {
        s.position[which] = value;
        s.positionSigma[which] = sigma;
        if ((s.haveMask & 7) == 0) {
            s.refMjd = mjd;
            s.refSod = sod;
        }
    } else {
        s.velocity[which - 3] = value;
        s.velocitySigma[which - 3] = sigma;
    }
    s.haveMask |= 1 << which;
}

}  // namespace

SinexReadResult parseSinex(std::string_view given, const std::string& source) {
    SinexReadResult res;
    std::string storage;
    const std::string_view text = plainText(given, &storage);
    const std::string src = source.empty() ? "sinex" : source;
    try {
        res.file.path = source;
        if (std::string e = textFileProblem(text, src, "SINEX"); !e.empty()) {
            res.error = std::move(e);
            return res;
        }
        size_t dropped = 0;
        auto warn = [&](std::string w) {
            if (res.warnings.size() < 500) res.warnings.push_back(std::move(w));
            else ++dropped;
        };
        std::string block;
        bool sawHeader = false;
        std::map<std::string, size_t> solIndex;            // code|point|soln -> solutions index
        std::map<std::string, Validity> validity;           // code|point|soln -> interval
        size_t pos = 0;
        long lineNo = 0;
        while (pos < text.size()) {
            size_t end = text.find('\n', pos);
            if (end == std::string_view::npos) end = text.size();
            std::string_view line = text.substr(pos, end - pos);
            pos = end + 1;
            ++lineNo;
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            if (line.empty()) continue;
            if (lineNo == 1 || !sawHeader) {
                if (line.substr(0, 5) != "%=SNX") {
                    res.error = whereInFile(src, lineNo) + "not a SINEX file: first line is \"" + printableExcerpt(line) + "\" (expected %=SNX)";
                    return res;
                }
                sawHeader = true;
                continue;
            }
            const char c0 = line[0];
            if (c0 == '*') continue;
            if (c0 == '%') {
                if (line.substr(0, 7) == "%ENDSNX") break;
                continue;
            }
            if (c0 == '+') {
                if (!block.empty()) warn(whereInFile(src, lineNo) + "block " + block + " not closed before " + printableExcerpt(line));
                block = std::string(trim(line.substr(1)));
                continue;
            }
            if (c0 == '-') {
                const std::string name(trim(line.substr(1)));
                if (name != block) warn(whereInFile(src, lineNo) + "end of block " + printableExcerpt(name) + " while in " + block);
                block.clear();
                continue;
            }
            if (c0 != ' ') {
                warn(whereInFile(src, lineNo) + "line does not start with a blank, '*', '+', '-' or '%'; ignored");
                continue;
            }
            if (block == "SITE/ID") {
                parseSiteLine(line, lineNo, src, warn, res.file);
            } else if (block == "SOLUTION/EPOCHS") {
                parseEpochsLine(line, lineNo, src, warn, validity);
            } else if (block == "SOLUTION/ESTIMATE") {
                parseEstimateLine(line, lineNo, src, warn, solIndex, res.file);
            }
        }
        if (!sawHeader) {
            res.error = src + ": not a SINEX file (no %=SNX header line)";
            return res;
        }
        for (auto& s : res.file.solutions) {
            auto v = validity.find(s.code + "|" + s.point + "|" + s.soln);
            if (v != validity.end()) {
                s.hasValidity = true;
                s.validFromMjd = v->second.from;
                s.validToMjd = v->second.to;
            }
        }
        if (dropped) res.warnings.push_back("... and " + std::to_string(dropped) + " more warnings");
        if (res.file.solutions.empty()) {
            res.error = src + ": no station coordinates (STAX/STAY/STAZ in SOLUTION/ESTIMATE)";
            return res;
        }
        res.ok = true;
    } catch (const std::exception& e) {
        res = SinexReadResult();
        res.error = src + ": internal error: " + e.what();
    }
    return res;
}

SinexReadResult readSinex(const std::string& path) {
    std::string text, err;
    if (!readFileText(path, &text, &err)) {
        SinexReadResult r;
        r.error = err;
        return r;
    }
    return parseSinex(text, path);
}

StationPositionResult stationPosition(const SinexFile& sinex, const std::string& siteCode, long mjd, double sod) {
    StationPositionResult r;
    const std::string code(trim(siteCode));
    r.code = code;
    std::vector<const SinexSolution*> cands;
    for (const auto& s : sinex.solutions)
        if (s.code == code) cands.push_back(&s);
    if (cands.empty()) {
        r.error = "site " + code + " is not in " + (sinex.path.empty() ? std::string("the SINEX file") : sinex.path);
        return r;
    }
    const double t = static_cast<double>(mjd) + sod / kSecondsPerDay;
    const SinexSolution* best = nullptr;
    double bestDist = INFINITY;
    for (const SinexSolution* s : cands) {
        if ((s->haveMask & 7) != 7) continue;
        double dist = 0;
        if (s->hasValidity) dist = t < s->validFromMjd ? s->validFromMjd - t : (t > s->validToMjd ? t - s->validToMjd : 0);
        else dist = cands.size() == 1 ? 0 : 1e9;  // no validity interval: only trusted when alone
        if (dist < bestDist) {
            bestDist = dist;
            best = s;
        }
    }
    if (!best) {
        r.error = "site " + code + " has no complete STAX/STAY/STAZ estimate";
        return r;
    }
    if (bestDist > 0) {
        char buf[160];
        if (bestDist >= 1e9)
            std::snprintf(buf, sizeof buf, "site %s: %zu solutions without validity intervals; solution %s used", code.c_str(),
                          cands.size(), best->soln.c_str());
        else
            std::snprintf(buf, sizeof buf, "site %s: epoch is %.1f days outside every solution's validity; nearest (%s) used",
                          code.c_str(), bestDist, best->soln.c_str());
        r.warnings.push_back(buf);
    }
    if ((best->haveMask & 0x38) != 0x38) r.warnings.push_back("site " + code + ": no complete velocity; taken as zero");
    const double dtYears =
        (static_cast<double>(mjd - best->refMjd) + (sod - best->refSod) / kSecondsPerDay) / 365.25;
    const Eigen::Vector3d vel = (best->haveMask & 0x38) == 0x38 ? best->velocity : Eigen::Vector3d::Zero();
    r.position = best->position + vel * dtYears;
    r.velocity = vel;
    r.soln = best->soln;
    for (const auto& s : sinex.sites)
        if (s.code == code) {
            r.description = s.description;
            break;
        }
    r.ok = true;
    return r;
}

StationPositionResult stationPositionByPad(const SinexFile& sinex, int cdpPadId, long mjd, double sod) {
    if (cdpPadId < 0 || cdpPadId > 9999) {
        StationPositionResult r;
        r.error = "CDP pad id " + std::to_string(cdpPadId) + " is not a 4-digit number";
        return r;
    }
    char code[8];
    std::snprintf(code, sizeof code, "%04d", cdpPadId);
    for (const auto& s : sinex.solutions)
        if (s.code == code) return stationPosition(sinex, code, mjd, sod);
    for (const auto& site : sinex.sites)
        if (site.cdpSod.size() == 8 && site.cdpSod.compare(0, 4, code) == 0) {
            StationPositionResult r = stationPosition(sinex, site.code, mjd, sod);
            if (r.ok) r.warnings.push_back(std::string("CDP pad ") + code + " found as site " + site.code + " (SITE/ID CDP-SOD)");
            return r;
        }
    StationPositionResult r;
    r.error = std::string("CDP pad id ") + code + " is not in " +
              (sinex.path.empty() ? std::string("the SINEX file") : sinex.path);
    return r;
}

}  // namespace lwb::core::slr
