#include "core/footprint/tune.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/folder.hpp"
#include "core/common/provenance.hpp"
#include "core/common/text.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/shot_list.hpp"

namespace lwb::core::footprint {

// ---- the confusion table ----

int VerdictConfusion::total() const {
    int n = 0;
    for (const auto& row : count)
        for (int v : row) n += v;
    return n;
}
int VerdictConfusion::analystGood() const { return count[0][0] + count[0][1] + count[0][2]; }
int VerdictConfusion::analystNotGood() const { return total() - analystGood(); }
int VerdictConfusion::falseDoubts() const { return count[0][1] + count[0][2]; }
int VerdictConfusion::misses() const { return count[1][0] + count[2][0]; }
int VerdictConfusion::disagreements() const { return total() - count[0][0] - count[1][1] - count[2][2]; }

Json VerdictConfusion::toJson() const {
    Json j = Json::object();
    for (int a = 0; a < 3; ++a) {
        Json row = Json::object();
        for (int c = 0; c < 3; ++c) row[verdictName(static_cast<Verdict>(c))] = count[a][c];
        j[verdictName(static_cast<Verdict>(a))] = row;
    }
    j["false_doubts"] = falseDoubts();
    j["misses"] = misses();
    return j;
}

std::string VerdictConfusion::text(const std::string& indent) const {
    auto cell = [](const std::string& s, size_t w) { return std::string(w > s.size() ? w - s.size() : 0, ' ') + s; };
    std::string t = indent + cell("analyst \\ computed", 20);
    for (int c = 0; c < 3; ++c) t += cell(verdictName(static_cast<Verdict>(c)), 10);
    t += "\n";
    for (int a = 0; a < 3; ++a) {
        t += indent + cell(verdictName(static_cast<Verdict>(a)), 20);
        for (int c = 0; c < 3; ++c) t += cell(std::to_string(count[a][c]), 10);
        t += "\n";
    }
    auto pct = [](int k, int n) { return n > 0 ? formatFixed(100.0 * k / n, 1) + " %" : std::string("-"); };
    t += indent + "false doubts " + std::to_string(falseDoubts()) + " of " + std::to_string(analystGood()) + " good (" +
         pct(falseDoubts(), analystGood()) + "), misses " + std::to_string(misses()) + " of " +
         std::to_string(analystNotGood()) + " not good (" + pct(misses(), analystNotGood()) + ")\n";
    return t;
}

namespace {

// ---- the thresholds the search moves ----

// One threshold: a schema row of the verdict (an end of a range row, or a value row), the
// measure it is compared with, and which side passes.
struct Knob {
    const char* key;
    int end;             // range rows: 0 lo, 1 hi, 2 both (a range about 0: ±value); value rows: -1
    const char* onKey;   // the boolean row that switches it on (nullptr: the row itself says)
    double (*measure)(const VerdictMeasures&);
    bool upper;          // passes with the measure below the threshold (else above it)
};

const Knob kKnobs[] = {
    {"verdict.axis_ratio", 0, nullptr, [](const VerdictMeasures& m) { return m.axisRatio; }, false},
    {"verdict.axis_ratio", 1, nullptr, [](const VerdictMeasures& m) { return m.axisRatio; }, true},
    {"verdict.major_axis_px", 0, nullptr, [](const VerdictMeasures& m) { return m.majorAxisPx; }, false},
    {"verdict.major_axis_px", 1, nullptr, [](const VerdictMeasures& m) { return m.majorAxisPx; }, true},
    // A tilt range about 0 (the spot's orientation has no preferred sign) moves as one: |tilt|.
    {"verdict.tilt_deg", 2, nullptr, [](const VerdictMeasures& m) { return std::fabs(m.tiltDeg); }, true},
    {"verdict.tilt_deg", 0, nullptr, [](const VerdictMeasures& m) { return m.tiltDeg; }, false},
    {"verdict.tilt_deg", 1, nullptr, [](const VerdictMeasures& m) { return m.tiltDeg; }, true},
    {"verdict.eccentricity", 0, nullptr, [](const VerdictMeasures& m) { return m.eccentricity; }, false},
    {"verdict.eccentricity", 1, nullptr, [](const VerdictMeasures& m) { return m.eccentricity; }, true},
    {"verdict.mse_max", -1, nullptr, [](const VerdictMeasures& m) { return m.mse; }, true},
    {"verdict.max_uncertainty_px", -1, nullptr, [](const VerdictMeasures& m) { return m.uncertaintyPx; }, true},
    {"verdict.edge_extent", -1, "verdict.check_edge", [](const VerdictMeasures& m) { return m.edgeRoom; }, false},
    {"verdict.saturation_max_pixels", -1, "verdict.check_saturation",
     [](const VerdictMeasures& m) { return static_cast<double>(m.saturatedPixels); }, true},
    {"verdict.second_spot_fraction", -1, "verdict.check_second_spot",
     [](const VerdictMeasures& m) { return m.secondPeakFraction; }, true},
};

using Field = Schema<FootprintParams>::Field;
const Field& fieldOf(const char* key) { return *footprintSchema().find(key); }

const char* knobEnd(const Knob& k) { return k.end == 0 ? "lo" : k.end == 1 ? "hi" : k.end == 2 ? "±" : ""; }

bool knobOn(const Knob& k, const FootprintParams& p) {
    const Field& f = fieldOf(k.key);
    if (k.end >= 0) {
        const RangeValue r = f.getRange(p);
        // A range about 0 moves as one (end 2); its ends alone only when it is not.
        const bool symmetric = r.lo == -r.hi && r.hi > 0;
        const bool hasBoth = std::any_of(std::begin(kKnobs), std::end(kKnobs),
                                         [&](const Knob& o) { return o.end == 2 && std::string(o.key) == k.key; });
        return r.enabled && (k.end == 2 ? symmetric : !(symmetric && hasBoth));
    }
    if (k.onKey) return fieldOf(k.onKey).get(p) != 0;
    return !std::isnan(f.get(p));  // off is NaN (mse_max, max_uncertainty_px)
}

double knobValue(const Knob& k, const FootprintParams& p) {
    const Field& f = fieldOf(k.key);
    if (k.end < 0) return f.get(p);
    const RangeValue r = f.getRange(p);
    return k.end == 0 ? r.lo : r.hi;  // (both: the upper end, the lower being its negative)
}

void setKnob(const Knob& k, FootprintParams* p, double v) {
    const Field& f = fieldOf(k.key);
    if (k.end < 0) return f.set(*p, v);
    RangeValue r = f.getRange(*p);
    if (k.end == 2)
        r.lo = -v, r.hi = v;
    else
        (k.end == 0 ? r.lo : r.hi) = v;
    f.setRange(*p, r);
}

// The threshold at which every shot passes the knob (its criterion left out).
void openKnob(const Knob& k, FootprintParams* p) {
    const bool integer = fieldOf(k.key).kind == FieldKind::Integer;
    setKnob(k, p, integer ? 1e9 : k.upper ? INFINITY : -INFINITY);
}

// A value the schema row accepts and that keeps a range's ends in order; NaN when none near.
double admissible(const Knob& k, const FootprintParams& p, double v) {
    const Field& f = fieldOf(k.key);
    if (f.kind == FieldKind::Integer) v = k.upper ? std::floor(v) : std::ceil(v);
    const Interval& iv = f.valid;
    if (v < iv.lo || (iv.loOpen && v <= iv.lo)) v = iv.loOpen ? iv.lo + 1e-9 * std::max(1.0, std::fabs(iv.lo)) : iv.lo;
    if (v > iv.hi || (iv.hiOpen && v >= iv.hi)) v = iv.hiOpen ? iv.hi - 1e-9 * std::max(1.0, std::fabs(iv.hi)) : iv.hi;
    if (!f.accepts(v)) return NAN;
    if (k.end == 2 && (v < 0 || !f.accepts(-v))) return NAN;
    if (k.end == 0 || k.end == 1) {
        const RangeValue r = f.getRange(p);
        if (k.end == 0 ? v > r.hi : v < r.lo) return NAN;
    }
    return v;
}

bool isGood(const VerdictMeasures& m, const FootprintParams& p) { return checkVerdict(m, p.verdict) == Verdict::Good; }

struct Score {
    int falseDoubts = 0, misses = 0;
    int errors() const { return falseDoubts + misses; }
};

Score scoreOf(const std::vector<const LabelledShot*>& shots, const FootprintParams& p) {
    Score s;
    for (const LabelledShot* l : shots) {
        const bool good = isGood(l->measures, p);
        if (l->label == Verdict::Good && !good) ++s.falseDoubts;
        if (l->label != Verdict::Good && good) ++s.misses;
    }
    return s;
}

// Where in the run of best values a moved threshold goes, from the side whose values pass (the
// last value let through, mostly a good shot's) towards the first value held back (mostly a
// not-good one's): a quarter of the way. The middle (0.5) let 0.4-2 % of held-out not-good shots
// through on simulated sets (double spots past a second-spot fraction moved to 0.61); the
// population's not-good values reach further in than a sample's.
constexpr double kGoodSide = 0.25;

// The best threshold of one knob with the others fixed: the fewest errors with no more misses
// than `maxMisses`, then the fewest misses; the current value when it is among the best, else
// kGoodSide into the best run of values (the run nearest the current one).
struct Move {
    bool found = false;
    double value = NAN;
    Score score;
};

Move bestMove(const Knob& k, const std::vector<const LabelledShot*>& shots, const FootprintParams& p, int maxMisses) {
    FootprintParams open = p;
    openKnob(k, &open);
    // The shots that pass every other criterion decide; the others keep their counts.
    int fixedFalseDoubts = 0, alwaysBad = 0;
    std::vector<std::pair<double, bool>> vals;  // (measure, analyst good) of the deciding shots
    for (const LabelledShot* l : shots) {
        const bool labelGood = l->label == Verdict::Good;
        if (!isGood(l->measures, open)) {
            fixedFalseDoubts += labelGood;
            continue;
        }
        const double v = k.measure(l->measures);
        if (std::isnan(v)) {  // a criterion without its value is skipped: passes, whatever the threshold
            alwaysBad += !labelGood;
            continue;
        }
        vals.emplace_back(k.upper ? v : -v, labelGood);  // as an upper threshold
    }
    std::sort(vals.begin(), vals.end());
    const double current = k.upper ? knobValue(k, p) : -knobValue(k, p);
    // Runs of values: cut j lets the first j deciding shots pass (values[j-1] < t < values[j]).
    std::vector<size_t> cuts{0};
    for (size_t i = 1; i <= vals.size(); ++i)
        if (i == vals.size() || vals[i].first > vals[i - 1].first) cuts.push_back(i);
    int goodTotal = 0;
    for (const auto& v : vals) goodTotal += v.second;
    std::vector<Score> scores(cuts.size());
    {
        int passGood = 0, passBad = 0;
        size_t i = 0;
        for (size_t c = 0; c < cuts.size(); ++c) {
            for (; i < cuts[c]; ++i) (vals[i].second ? passGood : passBad)++;
            scores[c].falseDoubts = fixedFalseDoubts + goodTotal - passGood;
            scores[c].misses = alwaysBad + passBad;
        }
    }
    auto lowEdge = [&](size_t c) { return c == 0 ? -INFINITY : vals[cuts[c] - 1].first; };
    auto highEdge = [&](size_t c) { return cuts[c] == vals.size() ? INFINITY : vals[cuts[c]].first; };
    auto better = [](const Score& a, const Score& b) {
        return a.errors() != b.errors() ? a.errors() < b.errors() : a.misses < b.misses;
    };
    size_t best = cuts.size();
    for (size_t c = 0; c < cuts.size(); ++c)
        if (scores[c].misses <= maxMisses && (best == cuts.size() || better(scores[c], scores[best]))) best = c;
    Move m;
    if (best == cuts.size()) return m;
    const Score target = scores[best];
    auto same = [&](size_t c) { return scores[c].errors() == target.errors() && scores[c].misses == target.misses; };
    // The cut holding the current value (values equal to it pass for ≤, fail for <: either).
    size_t here = 0;
    while (here + 1 < cuts.size() && !(current < highEdge(here))) ++here;
    if (same(here)) {
        m.found = true, m.value = knobValue(k, p), m.score = target;
        return m;
    }
    // The runs of best cuts; the one nearest the current value.
    double bestLo = NAN, bestHi = NAN, bestDist = INFINITY;
    for (size_t c = 0; c < cuts.size();) {
        if (!same(c)) {
            ++c;
            continue;
        }
        size_t e = c;
        while (e + 1 < cuts.size() && same(e + 1)) ++e;
        const double lo = lowEdge(c), hi = highEdge(e);
        const double dist = current < lo ? lo - current : current > hi ? current - hi : 0;
        if (dist < bestDist) bestDist = dist, bestLo = lo, bestHi = hi;
        c = e + 1;
    }
    double t;
    if (std::isfinite(bestLo) && std::isfinite(bestHi)) {
        t = bestLo + kGoodSide * (bestHi - bestLo);
    } else if (std::isfinite(bestLo)) {  // every deciding shot above bestLo passes: beyond the last by the run's width
        const double first = vals.empty() ? bestLo : vals.front().first;
        t = vals.back().first + std::max(vals.back().first - bestLo, 0.05 * std::max(std::fabs(vals.back().first - first), std::fabs(vals.back().first)));
        t = std::max(t, std::nextafter(vals.back().first, INFINITY));
    } else if (std::isfinite(bestHi)) {  // none may pass: below the first by as much
        const double last = vals.empty() ? bestHi : vals.back().first;
        t = bestHi - 0.05 * std::max(std::fabs(last - bestHi), std::fabs(bestHi));
        t = std::min(t, std::nextafter(bestHi, -INFINITY));
    } else {
        return m;
    }
    const double v = admissible(k, p, k.upper ? t : -t);
    if (std::isnan(v)) return m;
    FootprintParams q = p;
    setKnob(k, &q, v);
    m.score = scoreOf(shots, q);  // the admissible value may fall in another run
    m.found = m.score.misses <= maxMisses;
    m.value = v;
    return m;
}

// The search from `start` on `shots`: moves of one knob at a time, the best first, while they
// remove an error.
FootprintParams search(const std::vector<const LabelledShot*>& shots, const FootprintParams& start, Feedback* fb) {
    FootprintParams p = start;
    const int maxMisses = scoreOf(shots, start).misses;
    Score now = scoreOf(shots, p);
    for (int round = 0; round < 50 && now.errors() > 0 && !cancelled(fb); ++round) {
        const Knob* bestKnob = nullptr;
        Move best;
        for (const Knob& k : kKnobs) {
            if (!knobOn(k, p)) continue;
            const Move m = bestMove(k, shots, p, maxMisses);
            if (!m.found || m.score.errors() >= now.errors()) continue;
            if (!bestKnob || m.score.errors() < best.score.errors() ||
                (m.score.errors() == best.score.errors() && m.score.misses < best.score.misses))
                bestKnob = &k, best = m;
        }
        if (!bestKnob) break;
        setKnob(*bestKnob, &p, best.value);
        now = best.score;
    }
    return p;
}

// The fold of a shot: FNV-1a of its name without the folders (the same folds wherever the set is).
uint64_t nameHash(const std::string& s) {
    uint64_t h = 1469598103934665603ull;
    const size_t slash = s.find_last_of('/');
    for (size_t i = slash == std::string::npos ? 0 : slash + 1; i < s.size(); ++i)
        h = (h ^ static_cast<unsigned char>(s[i])) * 1099511628211ull;
    return h;
}

}  // namespace

VerdictTuneResult tuneVerdict(const std::vector<LabelledShot>& shots, const FootprintParams& start, int folds, Feedback* fb) {
    VerdictTuneResult r;
    r.before = r.after = start;
    int good = 0;
    for (const LabelledShot& s : shots) good += s.label == Verdict::Good;
    if (shots.size() < 10) {
        r.error = "too few shots with a verdict to tune on (" + std::to_string(shots.size()) + "; at least 10)";
        return r;
    }
    if (good == 0 || good == static_cast<int>(shots.size())) {
        r.error = std::string("every shot with a verdict is ") + (good == 0 ? "not good" : "good") +
                  ": the criteria are tuned on shots of both kinds";
        return r;
    }
    if (folds < 0 || folds == 1 || folds > 20) {
        r.error = "folds must be 0 (none) or 2..20, not " + std::to_string(folds);
        return r;
    }
    std::vector<const LabelledShot*> all;
    for (const LabelledShot& s : shots) all.push_back(&s);
    if (fb) fb->setProgress(0);
    r.after = search(all, start, fb);
    for (const LabelledShot& s : shots) {
        r.confusionBefore.add(s.label, checkVerdict(s.measures, start.verdict));
        r.confusionAfter.add(s.label, checkVerdict(s.measures, r.after.verdict));
    }
    for (const Knob& k : kKnobs)
        if (knobOn(k, start) && knobValue(k, start) != knobValue(k, r.after))
            r.changes.push_back({k.key, knobEnd(k), knobValue(k, start), knobValue(k, r.after)});
    // Cross-validation: folds by the shots' names (the same shots, the same folds).
    r.folds = static_cast<int>(std::min<size_t>(static_cast<size_t>(folds), shots.size() / 5));
    if (r.folds < 2) r.folds = 0;
    for (int f = 0; f < r.folds && !cancelled(fb); ++f) {
        std::vector<const LabelledShot*> train, test;
        for (const LabelledShot& s : shots)
            (static_cast<int>(nameHash(s.name) % static_cast<uint64_t>(r.folds)) == f ? test : train).push_back(&s);
        const FootprintParams tuned = search(train, start, fb);
        for (const LabelledShot* s : test) r.heldOut.add(s->label, checkVerdict(s->measures, tuned.verdict));
        if (fb) fb->setProgress(double(f + 1) / (r.folds + 1));
    }
    if (cancelled(fb)) {
        r.error = "cancelled";
        return r;
    }
    r.ok = true;
    return r;
}

CriterionSweep sweepCriterion(const std::vector<VerdictMeasures>& shots, const std::vector<int>& labels,
                              const FootprintParams& p, const std::string& key, const std::string& end,
                              const std::vector<double>& values, Feedback* fb) {
    CriterionSweep out;
    const Field* f = footprintSchema().find(key);
    if (!f || key.rfind("verdict.", 0) != 0 || (f->kind == FieldKind::Range) != (end == "lo" || end == "hi") ||
        !(f->kind == FieldKind::Range || f->kind == FieldKind::Real || f->kind == FieldKind::Integer))
        return out;
    std::vector<bool> now(shots.size());
    for (size_t i = 0; i < shots.size(); ++i) now[i] = isGood(shots[i], p);
    for (size_t i = 0; i < labels.size() && i < shots.size(); ++i) out.labelled += labels[i] >= 0;
    FootprintParams q = p;
    for (double v : values) {
        if (cancelled(fb)) return {};
        if (f->kind == FieldKind::Range) {
            RangeValue r = f->getRange(p);
            (end == "lo" ? r.lo : r.hi) = v;
            f->setRange(q, r);
        } else {
            f->set(q, v);
        }
        int good = 0, changed = 0, disagree = 0;
        for (size_t i = 0; i < shots.size(); ++i) {
            const bool g = isGood(shots[i], q);
            good += g;
            changed += g != now[i];
            if (i < labels.size() && labels[i] >= 0) disagree += g != (labels[i] == static_cast<int>(Verdict::Good));
        }
        out.good.push_back(good);
        out.changed.push_back(changed);
        out.disagree.push_back(disagree);
    }
    return out;
}

// ---- from files ----

namespace {

struct VerdictRow {
    std::string file;
    int roi = -1;  // -1: the frame's one ROI
    Verdict verdict = Verdict::Good;
    long line = 0;
};

bool readVerdicts(const std::string& path, std::vector<VerdictRow>* rows, std::vector<std::string>* notes,
                  FootprintError* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = {csv.error, false};
        return false;
    }
    const CsvTable& t = csv.table;
    const int cf = t.column("file"), cv = t.column("verdict"), cr = t.column("roi");
    // The workbench's review export: `verdict` is the one shown (the computed one where the
    // analyst set none); only the rows its `override` column marks manual are the analyst's.
    const int co = t.column("override");
    size_t computed = 0;
    if (cf < 0 || cv < 0) {
        *error = {path + ":1: a verdicts table needs 'file' and 'verdict' columns (the workbench's review export, a "
                         "footprint report)",
                  false};
        return false;
    }
    size_t skipped = 0;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const std::vector<std::string>& row = t.rows[i];
        if (co >= 0 && trim(row[static_cast<size_t>(co)]).empty()) {
            ++computed;
            continue;
        }
        VerdictRow v;
        v.line = t.lines[i];
        const std::string text(trim(row[static_cast<size_t>(cv)]));
        if (text.empty() || toLower(text) == "unreadable") {
            ++skipped;
            continue;
        }
        if (!parseVerdict(text, &v.verdict)) {
            *error = {whereInFile(path, v.line) + "verdict \"" + text + "\" is not good, doubtful or rejected", false};
            return false;
        }
        v.file = std::string(trim(row[static_cast<size_t>(cf)]));
        if (v.file.empty()) {
            *error = {whereInFile(path, v.line) + "the file is empty", false};
            return false;
        }
        // A relative file: relative to the table's folder, else (a report written elsewhere) to
        // the working folder.
        if (v.file[0] != '/' && !folderWithSlash(path).empty() && (pathExists(folderWithSlash(path) + v.file) || !pathExists(v.file)))
            v.file = folderWithSlash(path) + v.file;
        if (cr >= 0) {
            const std::string r(trim(row[static_cast<size_t>(cr)]));
            long long k = 0;
            if (!r.empty() && (!parseLong(r, &k) || k < 0 || k > 1000)) {
                *error = {whereInFile(path, v.line) + "roi \"" + r + "\" is not a ROI index (0, 1, ...)", false};
                return false;
            }
            v.roi = r.empty() ? -1 : static_cast<int>(k);
        }
        rows->push_back(v);
    }
    if (skipped) notes->push_back(std::to_string(skipped) + " row(s) of " + path + " without a verdict (empty or unreadable) left out");
    if (computed)
        notes->push_back(std::to_string(computed) + " row(s) of " + path +
                         " with the computed verdict only (no manual one in its override column) left out");
    return true;
}

}  // namespace

FootprintTuneResult tuneFootprint(const FootprintTuneSources& src, Feedback* fb) {
    FootprintTuneResult r;
    if (src.verdicts.empty()) {
        r.error = {"no verdicts table (the analyst's verdicts are what the criteria are tuned on)", true};
        return r;
    }
    FootprintSetup setup;
    if (!setUpFootprintRun(src.run, &setup, &r.error)) return r;
    std::vector<VerdictRow> rows;
    if (!readVerdicts(src.verdicts, &rows, &r.notes, &r.error)) return r;
    FrameIndex index;
    for (size_t k = 0; k < rows.size(); ++k) {
        index.add(rows[k].file, k);
        for (size_t other : index.atPath(rows[k].file))
            if (other != k && (rows[other].roi == rows[k].roi || rows[other].roi < 0 || rows[k].roi < 0)) {
                r.error = {whereInFile(src.verdicts, rows[k].line) + rows[k].file + " has a verdict at line " +
                               std::to_string(rows[other].line) + " already" +
                               (rows[k].roi < 0 ? " (a frame of several ROIs: give a roi column)" : ""),
                           false};
                return r;
            }
    }
    // Every shot fitted once under the starting parameters.
    Feedback inner([&](double f) {
        if (fb) fb->setProgress(0.8 * f);
    });
    BatchResult batch = runFootprintBatch(setup.shots, setup.params, &inner, [&](size_t, const BatchItem&) {
        if (cancelled(fb)) inner.cancel();
    });
    if (batch.cancelled || cancelled(fb)) {
        r.error = {"cancelled", false};
        return r;
    }
    r.shots = batch.items.size();
    for (const ShotSpec& s : setup.shots) r.inputs.push_back(s.file);
    r.unreadable = batch.readErrors;
    std::vector<LabelledShot> labelled;
    std::vector<bool> used(rows.size(), false);
    // A row found by a file name alone labels a frame only when no other input frame has that name.
    std::map<std::string, int> inputsNamed;
    for (const BatchItem& item : batch.items) ++inputsNamed[item.file.substr(item.file.find_last_of('/') + 1)];
    size_t ambiguous = 0;
    for (const BatchItem& item : batch.items) {
        r.rois += item.rois.size();
        if (!item.readError.empty()) continue;
        const bool byPath = !index.atPath(item.file).empty();
        if (!byPath && inputsNamed[item.file.substr(item.file.find_last_of('/') + 1)] > 1 && !index.rowsOf(item.file).empty()) {
            ++ambiguous;
            continue;
        }
        const std::vector<size_t>& mine = index.rowsOf(item.file);
        for (size_t k = 0; k < item.rois.size(); ++k) {
            const VerdictRow* row = nullptr;
            for (size_t m : mine)
                if (rows[m].roi == static_cast<int>(k) || (rows[m].roi < 0 && item.rois.size() == 1)) row = &rows[m], used[m] = true;
            if (!row && !mine.empty() && item.rois.size() > 1 && rows[mine.front()].roi < 0) {
                r.error = {whereInFile(src.verdicts, rows[mine.front()].line) + item.file + " has " +
                               std::to_string(item.rois.size()) + " ROIs: a verdicts table for frames of several ROIs "
                               "needs a roi column",
                           false};
                return r;
            }
            if (!row) continue;
            const FootprintResult& res = item.rois[k].result;
            LabelledShot l;
            l.name = item.rois.size() > 1 ? item.file + " roi " + std::to_string(k) : item.file;
            l.measures = measureResult(res, res.domain.width, res.domain.height);
            if (!res.ok) l.measures.refusal = res.error.empty() ? "not processed" : res.error;
            l.label = row->verdict;
            labelled.push_back(std::move(l));
        }
    }
    for (bool u : used) r.unmatchedRows += !u;
    r.labelled = labelled.size();
    if (r.unmatchedRows)
        r.notes.push_back(std::to_string(r.unmatchedRows) + " verdict row(s) name no shot of the inputs (left out)");
    if (r.rois > r.labelled)
        r.notes.push_back(std::to_string(r.rois - r.labelled) + " ROI(s) of the inputs have no verdict (not tuned on)");
    if (r.unreadable) r.notes.push_back(std::to_string(r.unreadable) + " frame(s) could not be read (left out)");
    if (ambiguous)
        r.notes.push_back(std::to_string(ambiguous) + " frame(s) share a file name with another input and have no row by "
                          "their path: not labelled (a row by name alone would label them all)");
    if (labelled.empty()) {
        r.error = {"no shot of the inputs has a verdict in " + src.verdicts +
                       " (rows are matched by the frame's path, else by its file name)",
                   true};
        return r;
    }
    Feedback tuneFb([&](double f) {  // (the caller's Cancel reaches the tuning at its next step)
        if (cancelled(fb)) tuneFb.cancel();
        if (fb) fb->setProgress(0.8 + 0.2 * f);
    });
    r.tuning = runTask<VerdictTuneTask>({std::move(labelled), src.folds}, setup.params.footprint, &tuneFb);
    if (!r.tuning.ok) {
        r.error = {r.tuning.error, r.tuning.error != "cancelled"};
        return r;
    }
    r.ok = true;
    return r;
}

Json footprintTuneSummary(const FootprintTuneResult& r) {
    Json j = Json::object();
    j["shots"] = r.shots;
    j["rois"] = r.rois;
    j["labelled"] = r.labelled;
    j["unreadable"] = r.unreadable;
    j["unmatched_verdict_rows"] = r.unmatchedRows;
    Json changes = Json::array();
    for (const VerdictChange& c : r.tuning.changes) changes.push_back({{"key", c.key}, {"end", c.end}, {"before", c.before}, {"after", c.after}});
    j["changes"] = changes;
    j["confusion_before"] = r.tuning.confusionBefore.toJson();
    j["confusion_after"] = r.tuning.confusionAfter.toJson();
    j["folds"] = r.tuning.folds;
    if (r.tuning.folds) j["confusion_held_out"] = r.tuning.heldOut.toJson();
    j["notes"] = r.notes;
    return j;
}

bool writeTunedFootprintConfig(const FootprintTuneResult& r, const FootprintTuneSources& src, const std::string& path,
                               std::string* error) {
    if (!r.ok) {
        *error = "no tuning to write";
        return false;
    }
    Provenance prov;
    prov.command = "footprint tune";
    prov.parameters = footprintParamsToJson(r.tuning.after);
    prov.settings = footprintTuneSummary(r);
    prov.inputs = r.inputs;
    prov.inputs.push_back(src.verdicts);
    if (!src.run.configFile.empty()) prov.inputs.push_back(src.run.configFile);
    const std::string text = dumpJson(prov.parameters);
    return writeWithProvenance(prov, path, [&](const std::string& to, std::string* err) { return writeFileAtomic(to, text, err); },
                               error);
}

}  // namespace lwb::core::footprint
