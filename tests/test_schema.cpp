// The parameter schema tables (issue 9): every field of every table survives every path —
// JSON (configs, --print-config), --set key=value, SLR presets, footprint config files — and a
// field's accessor touches that field only. A field left out of any path fails here.
#include <QtTest>
#include <QDir>
#include <QRegularExpression>
#include <map>
#include <set>

#include "core/calib/calib_params.hpp"
#include "core/common/json.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/footprint/trend.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/slr/presets.hpp"
#include "core/slr/slr_params.hpp"
#include "schema_cases.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using lwb::test::joined;
using lwb::test::otherValue;
using lwb::test::setOtherValue;

namespace {

// Every field on its own: other value -> JSON text -> parsed -> over the defaults.
template <class P>
void everyFieldThroughJson(const Schema<P>& schema) {
    QVERIFY(!schema.fields().empty());
    const P def{};
    const Json written = schema.toJson(def);
    for (const auto& f : schema.fields()) {
        // Its doc is the field's tooltip, shown alone: a sentence of its own, not the tail of
        // the row before it (the GUI showed one that began "... or less than").
        QVERIFY2(!f.doc.empty() && f.doc.rfind("...", 0) != 0 && f.doc.rfind("\u2026", 0) != 0,
                 (schema.name() + "." + f.key + ": doc \"" + f.doc + "\" does not stand alone").c_str());
        // Always written, even at the default.
        const Json* v = &written;
        std::string path;
        for (size_t a = 0, b; a <= f.key.size(); a = b + 1) {
            b = f.key.find('.', a);
            if (b == std::string::npos) b = f.key.size();
            const std::string part = f.key.substr(a, b - a);
            QVERIFY2(v->is_object() && v->contains(part), (schema.name() + "." + f.key + " not written").c_str());
            v = &(*v)[part];
        }
        P base = def;
        const P p = otherValue(schema, f, &base);
        // The accessor touches this field and no other.
        QCOMPARE(QString::fromStdString(joined(schema.changedKeys(base, p))), QString::fromStdString(f.key));
        const JsonParseResult parsed = parseJson(dumpJson(schema.toJson(p)), "mem");
        QVERIFY2(parsed.ok, parsed.error.c_str());
        P back{};
        std::string err;
        QVERIFY2(schema.fromJson(parsed.value, &back, &err, &parsed), err.c_str());
        QVERIFY2(schema.changedKeys(p, back).empty(), (f.key + " lost: " + joined(schema.changedKeys(p, back))).c_str());
        // --set key=value with the value's own text (over the base: a rule may tie the field to others).
        P set = base;
        QVERIFY2(schema.setFromText(&set, f.key, schema.valueText(f, p), &err), (f.key + ": " + err).c_str());
        QVERIFY2(schema.changedKeys(p, set).empty(), (f.key + " via --set: " + joined(schema.changedKeys(p, set))).c_str());
    }
}

// Every field at once (as many as the rules allow together: all of them in today's tables).
template <class P>
P allOther(const Schema<P>& schema) {
    // The fields at special values first (automatic off needs the scale they fix), then the rest.
    P p{};
    std::set<std::string> done;
    for (int pass = 0; pass < 2; ++pass)
        for (const auto& f : schema.fields()) {
            if (done.count(f.key) || (pass == 0 && f.specials.empty())) continue;
            P q = p;
            if (f.kind == FieldKind::Text && f.key == "preset") f.setText(q, "yao2021");
            else if (!setOtherValue(schema, f, &q)) continue;
            p = q;
            done.insert(f.key);
        }
    return p;
}

}  // namespace

class TestSchema : public QObject {
    Q_OBJECT
private slots:
    void footprintEveryField() { everyFieldThroughJson(footprint::footprintSchema()); }
    void slrEveryField() { everyFieldThroughJson(slr::slrSchema()); }
    void trendEveryField() { everyFieldThroughJson(footprint::trendSchema()); }
    void calibEveryField() { everyFieldThroughJson(calib::calibSchema()); }
    void radiometryEveryField() { everyFieldThroughJson(radiometry::radiometrySchema()); }

    // Every field of the calibration and radiometry tables at once through JSON, and the
    // whole-struct checks (rules between fields) accept what the tables accept.
    void calibRadiometryAllFields() {
        std::string err;
        const auto& cs = calib::calibSchema();
        calib::CalibParams cp = allOther(cs);
        cp.pointing.fixRelativeRotation = cp.pointing.model == calib::CalibModel::DualBeam;  // the rule between them
        QVERIFY2(calib::validate(cp).empty(), calib::validate(cp).c_str());
        QVERIFY(cs.changedKeys(calib::CalibParams{}, cp).size() + 1 >= cs.fields().size());
        const JsonParseResult cj = parseJson(dumpJson(cs.toJson(cp)), "session.json");
        calib::CalibParams cback;
        QVERIFY2(cs.fromJson(cj.value, &cback, &err, &cj), err.c_str());
        QVERIFY2(cs.changedKeys(cp, cback).empty(), joined(cs.changedKeys(cp, cback)).c_str());

        const auto& rs = radiometry::radiometrySchema();
        const radiometry::RadiometryParams rp = allOther(rs);
        QCOMPARE(rs.changedKeys(radiometry::RadiometryParams{}, rp).size(), rs.fields().size());
        QVERIFY2(radiometry::validate(rp).empty(), radiometry::validate(rp).c_str());
        const JsonParseResult rj = parseJson(dumpJson(rs.toJson(rp)), "session.json");
        radiometry::RadiometryParams rback;
        QVERIFY2(rs.fromJson(rj.value, &rback, &err, &rj), err.c_str());
        QVERIFY2(rs.changedKeys(rp, rback).empty(), joined(rs.changedKeys(rp, rback)).c_str());
    }

    // The rules between fields are checked on the whole struct, so the order of --set does not
    // matter, and bad values name the key and the range.
    void calibRadiometryMessages() {
        std::string err;
        const auto& rs = radiometry::radiometrySchema();
        radiometry::RadiometryParams rp;
        QVERIFY2(rs.setFromText(&rp, "dn_min", "61000", &err), err.c_str());  // above dn_max for a moment
        QVERIFY(!radiometry::validate(rp).empty());
        QVERIFY2(rs.setFromText(&rp, "dn_max", "65000", &err), err.c_str());
        QVERIFY2(radiometry::validate(rp).empty(), radiometry::validate(rp).c_str());
        QVERIFY(!rs.setFromText(&rp, "mosaic.min_inliers", "3", &err));
        QVERIFY2(err.find("radiometry.mosaic.min_inliers") != std::string::npos && err.find("[4, 100000]") != std::string::npos,
                 err.c_str());
        const auto& cs = calib::calibSchema();
        calib::CalibParams cp;
        QVERIFY(!cs.setFromText(&cp, "detector.outlier_sigma", "2", &err));
        QVERIFY2(err.find("calib.detector.outlier_sigma") != std::string::npos, err.c_str());
        QVERIFY2(cs.setFromText(&cp, "detector.outlier_sigma", "off", &err), err.c_str());
        QCOMPARE(cp.detector.outlierSigma, 0.0);
        QVERIFY2(cs.setFromText(&cp, "pointing.sigma_attitude_urad", "2.5", &err), err.c_str());
        QCOMPARE(cp.pointing.sigmaAttitudeRad, 2.5e-6);
        QVERIFY2(cs.setFromText(&cp, "pointing.fix_relative", "true", &err), err.c_str());
        QVERIFY(!calib::validate(cp).empty());  // needs the dual model
        QVERIFY2(cs.setFromText(&cp, "pointing.model", "dual", &err), err.c_str());
        QVERIFY2(calib::validate(cp).empty(), calib::validate(cp).c_str());
        // Unknown keys are errors with line and column.
        const JsonParseResult j = parseJson("{\n  \"detector\": {\"trigger\": 5, \"trigerr\": 1}\n}", "cfg.json");
        QVERIFY(j.ok);
        calib::CalibParams back;
        QVERIFY(!cs.fromJson(j.value, &back, &err, &j));
        QVERIFY2(err.find("cfg.json:2:") != std::string::npos && err.find("trigerr") != std::string::npos, err.c_str());
    }

    void allFieldsTogether() {
        const auto& fs = footprint::footprintSchema();
        const footprint::FootprintParams fp = allOther(fs);
        QCOMPARE(fs.changedKeys(footprint::FootprintParams{}, fp).size(), fs.fields().size());
        footprint::FootprintParams fback;
        std::string err;
        // The config-file path (the user presets of the workbench are such files).
        const JsonParseResult fj = parseJson(dumpJson(footprint::footprintParamsToJson(fp)), "preset.json");
        QVERIFY2(fj.ok, fj.error.c_str());
        QVERIFY2(footprint::footprintParamsFromJson(fj.value, &fback, &err, &fj), err.c_str());
        QVERIFY2(fs.changedKeys(fp, fback).empty(), joined(fs.changedKeys(fp, fback)).c_str());

        const auto& ss = slr::slrSchema();
        const slr::SlrParams sp = allOther(ss);
        QCOMPARE(ss.changedKeys(slr::SlrParams{}, sp).size(), ss.fields().size());
        const JsonParseResult sj = parseJson(dumpJson(ss.toJson(sp)), "mem");
        slr::SlrParams sback;
        QVERIFY2(ss.fromJson(sj.value, &sback, &err, &sj), err.c_str());
        QVERIFY2(ss.changedKeys(sp, sback).empty(), joined(ss.changedKeys(sp, sback)).c_str());
    }

    // Each field of the SLR table through a satellite preset file and back.
    void slrPresetEveryField() {
        const auto& ss = slr::slrSchema();
        for (const auto& f : ss.fields()) {
            if (f.key.rfind("oc.", 0) == 0) continue;  // (not a satellite's: refused in a preset, test_slr_one_run)
            slr::SlrParams base;
            const slr::SlrParams p = otherValue(ss, f, &base);
            slr::SatellitePreset preset;
            preset.name = "LAGEOS-1";
            preset.ilrsId = "7603901";
            preset.screen = p.screen;
            preset.postfit = p.postfit;
            const JsonParseResult parsed = parseJson(dumpJson(slr::presetsToJson({preset})), "presets.json");
            QVERIFY2(parsed.ok, parsed.error.c_str());
            const slr::PresetsResult back = slr::presetsFromJson(parsed.value, "presets.json", &parsed);
            QVERIFY2(back.ok, (f.key + ": " + back.error).c_str());
            QCOMPARE(back.presets.size(), size_t(1));
            slr::SlrParams q;
            q.screen = back.presets[0].screen;
            q.postfit = back.presets[0].postfit;
            q.oc = p.oc;
            q.ownTrend = p.ownTrend;
            QVERIFY2(ss.changedKeys(p, q).empty(), (f.key + " lost in a preset: " + joined(ss.changedKeys(p, q))).c_str());
        }
    }

    // Values outside the UI range but valid are kept exactly (the issue's C = 0.8 and axis
    // ratio 5), and invalid ones are refused with the key and the range.
    // Fuzz finding 5 (fuzz_footprint_config): --set preset=<any text> was accepted, and the
    // config --print-config then wrote could not be read back.
    void footprintPresetMustBeKnown() {
        const auto& fs = footprint::footprintSchema();
        footprint::FootprintParams p;
        std::string err;
        QVERIFY(!fs.setFromText(&p, "preset", "bogus", &err));
        QVERIFY2(err.find("must be wu2021 or yao2021") != std::string::npos, err.c_str());
        QCOMPARE(QString::fromStdString(p.preset), QString("wu2021"));  // untouched on error
        QVERIFY2(fs.setFromText(&p, "preset", "yao2021", &err), err.c_str());
        const JsonParseResult back = parseJson(dumpJson(fs.toJson(p)), "mem");
        footprint::FootprintParams q;
        QVERIFY2(back.ok && footprint::footprintParamsFromJson(back.value, &q, &err, &back), err.c_str());
        QCOMPARE(QString::fromStdString(q.preset), QString("yao2021"));
    }

    void outsideUiRangeKept() {
        const auto& ss = slr::slrSchema();
        const auto* c = ss.find("screen.cosine_c");
        QVERIFY(c);
        QVERIFY(0.8 < c->uiLo);  // the case is outside the slider's range
        slr::SlrParams p;
        std::string err;
        QVERIFY2(ss.setFromText(&p, "screen.cosine_c", "0.8", &err), err.c_str());
        QCOMPARE(p.screen.cosineC, 0.8);
        QVERIFY(!ss.setFromText(&p, "screen.cosine_c", "1.2", &err));
        QVERIFY2(err.find("screen.cosine_c") != std::string::npos && err.find("[0.5, 1)") != std::string::npos, err.c_str());
        QCOMPARE(p.screen.cosineC, 0.8);  // untouched on error

        const auto& fs = footprint::footprintSchema();
        const auto* ar = fs.find("verdict.axis_ratio");
        QVERIFY(ar && ar->kind == FieldKind::Range);
        footprint::FootprintParams fp;
        QVERIFY2(fs.setFromText(&fp, "verdict.axis_ratio", "1,5", &err), err.c_str());
        QVERIFY(5 > ar->uiHi);
        const JsonParseResult j = parseJson(dumpJson(fs.toJson(fp)), "mem");
        footprint::FootprintParams back;
        QVERIFY2(fs.fromJson(j.value, &back, &err, &j), err.c_str());
        QCOMPARE(fs.valueText(*ar, back), std::string("1,5"));
        QCOMPARE(back.verdict.axisRatio.hi, 5.0);
    }

    // Issue 28: help text names no default by hand. (1) In the CLI's sources, a usage line of an
    // option that is an alias of a schema key ({"--flag", "key"}) states no default of its own:
    // a "default" followed by a value must be a {default:KEY} placeholder. (2) Every command's
    // --help has its placeholders filled with the schema rows' values.
    // Stages are tags on the rows (issue 28), not key prefixes: what a change reruns.
    void stagesComeFromTheRows() {
        using slr::SlrParams;
        const auto& ss = slr::slrSchema();
        const SlrParams d;
        for (const auto& f : ss.fields()) {  // every row has the stage of its part of the run
            const int want = f.key == "screen.cosine_c"          ? slr::kStageRecovery
                             : f.key.rfind("postfit.", 0) == 0 ? slr::kStagePostfit
                             : f.key.rfind("oc.", 0) == 0      ? slr::kStageOc
                                                                : slr::kStageScale;
            QVERIFY2(f.stage == want, f.key.c_str());
        }
        QCOMPARE(ss.firstChangedStage(d, d), -1);
        SlrParams p = d;
        p.postfit.degree = 3;
        QCOMPARE(ss.firstChangedStage(d, p), int(slr::kStagePostfit));
        p.screen.cosineC = 0.97;
        QCOMPARE(ss.firstChangedStage(d, p), int(slr::kStageRecovery));
        p.screen.magT = 2;
        QCOMPARE(ss.firstChangedStage(d, p), int(slr::kStageScale));
        p.oc.shapiro = false;  // the O-C: computed when the pass is opened, before everything
        QCOMPARE(ss.firstChangedStage(d, p), int(slr::kStageOc));

        using footprint::FootprintParams;
        const auto& fs = footprint::footprintSchema();
        const FootprintParams f0;
        FootprintParams f = f0;
        f.preset = "other";
        f.verdict.tiltDeg.hi = 20;
        QCOMPARE(fs.firstChangedStage(f0, f), int(footprint::kStageVerdict));
        QVERIFY(footprint::onlyVerdictDiffers(f0, f));
        f.camera.gainEPerDn = 3;  // the camera weights the fit
        QCOMPARE(fs.firstChangedStage(f0, f), int(footprint::kStageFit));
        QVERIFY(!footprint::onlyVerdictDiffers(f0, f));
        for (const auto& row : fs.fields())
            QVERIFY2((row.stage == footprint::kStageVerdict) == (row.key.rfind("verdict.", 0) == 0 || row.key == "preset"),
                     row.key.c_str());
    }

    void helpDefaultsComeFromTheSchema() {
        const QDir app(QString(LWB_SOURCE_DIR) + "/app");
        const QRegularExpression alias(R"re(\{"(--[a-z0-9-]+)",\s*"([a-z_.0-9]+)"\})re");
        const QRegularExpression handDefault(R"re(default[:]?\s+([-0-9a-z.]+))re");
        // The values a key may take that are words (a choice's names): "default akaze" restates one.
        auto choicesOf = [](const std::string& key) {
            std::set<QString> words;
            auto add = [&](const auto& schema) {
                if (const auto* f = schema.find(key); f && f->kind == FieldKind::Choice)
                    for (const auto& c : f->choices) words.insert(QString::fromStdString(c));
            };
            add(slr::slrSchema());
            add(calib::calibSchema());
            add(radiometry::radiometrySchema());
            add(footprint::footprintSchema());
            add(footprint::trendSchema());
            return words;
        };
        int aliases = 0, checked = 0;
        for (const QString& name : app.entryList({"cli_*.cpp"})) {
            const QString text = QString::fromUtf8(lwbtest::readAll(app.filePath(name)));
            std::map<QString, std::set<QString>> flags;  // flag → the word values of its key(s)
            for (auto it = alias.globalMatch(text); it.hasNext();) {
                const auto m = it.next();
                const std::set<QString> w = choicesOf(m.captured(2).toStdString());
                flags[m.captured(1)].insert(w.begin(), w.end());
            }
            aliases += int(flags.size());
            for (const QString& line : text.split('\n')) {
                const QString t = line.trimmed();
                if (!t.startsWith("\"  --")) continue;
                const QString flag = t.mid(3).section(QRegularExpression("[ ,=]"), 0, 0);
                if (!flags.count(flag)) continue;
                ++checked;
                for (auto m = handDefault.globalMatch(t); m.hasNext();) {
                    const auto match = m.next();
                    const QString d = match.captured(0), v = match.captured(1);
                    const bool number = v[0].isDigit() || (v.size() > 1 && v[0] == '-' && v[1].isDigit());
                    if (!number && !flags[flag].count(v)) continue;  // "default: no threshold" describes, not restates
                    QVERIFY2(false, qPrintable(name + ": " + flag + " states its default by hand (\"" + d +
                                               "\"): write {default:KEY}\n  " + t));
                }
            }
        }
        QVERIFY2(aliases >= 30 && checked >= 25, qPrintable(QString("%1 aliases, %2 lines").arg(aliases).arg(checked)));
        struct Help {
            QStringList cmd;
            QString shows;
        };
        slr::SlrParams sp;
        calib::CalibParams cp;
        radiometry::RadiometryParams rp;
        footprint::TrendParams tp;
        footprint::FootprintParams fp;
        auto val = [](const auto& schema, const auto& p, const char* key) {
            return QString::fromStdString(schema.valueText(*schema.find(key), p));
        };
        const QList<Help> helps = {
            {{"slr"}, "(default " + val(slr::slrSchema(), sp, "screen.cosine_c") + ")"},
            {{"footprint"}, "(default " + val(footprint::footprintSchema(), fp, "roi.size") + ")"},
            {{"trend"}, "(default " + val(footprint::trendSchema(), tp, "min_shots") + ")"},
            {{"calib", "detector"}, "(default " + val(calib::calibSchema(), cp, "detector.outlier_sigma") + ";"},
            {{"calib", "waveform"}, "(default " + val(calib::calibSchema(), cp, "waveform.sample_interval_ns") + ")"},
            {{"calib", "pointing"}, "(" + val(calib::calibSchema(), cp, "pointing.sigma_range") + " m)"},
            {{"radiometry", "mosaic"}, "(default " + val(radiometry::radiometrySchema(), rp, "mosaic.min_inliers") + ")"},
            {{"radiometry", "fit"}, "(default " + val(radiometry::radiometrySchema(), rp, "vm_pct") + " %)"},
            {{"radiometry", "apply"}, "(default " + val(radiometry::radiometrySchema(), rp, "limit_pct") + " %)"},
        };
        for (const Help& h : helps) {
            const lwbtest::CliRun r = lwbtest::runCli(h.cmd + QStringList{"--help"});
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(!r.out.contains("{default:"), qPrintable(h.cmd.join(' ') + ": an unfilled placeholder\n" + r.out));
            QVERIFY2(r.out.contains(h.shows), qPrintable(h.cmd.join(' ') + " --help lacks \"" + h.shows + "\""));
        }
    }
};

QTEST_GUILESS_MAIN(TestSchema)
#include "test_schema.moc"
