// Issue 28: the step functions' own checks (validate(DetectorFitParams), ...) take their ranges
// from the schema rows, declared once, instead of restating them by hand (about 36 checks did).
// A value outside a row's range is refused by the step itself, named by the row's key; the
// defaults pass; the rule between two fields that no row holds stays with the step.
#include <QtTest>
#include <functional>

#include "core/calib/calib_params.hpp"
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/waveform.hpp"
#include "core/radiometry/gcp.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/radiometry/reflectance.hpp"

using namespace lwb::core;

class TestSchemaValidators : public QObject {
    Q_OBJECT

    static void refusedNaming(const std::string& error, const char* key) {
        QVERIFY2(error.find(key) != std::string::npos, error.c_str());
    }

private slots:
    void defaultsPass() {
        QCOMPARE(calib::validate(calib::DetectorFitParams{}), std::string());
        QCOMPARE(calib::validate(calib::PointingCalibParams{}), std::string());
        QCOMPARE(calib::validate(calib::WaveformParams{}), std::string());
        QCOMPARE(calib::validate(calib::FeatureMatchParams{}), std::string());
        QCOMPARE(radiometry::validate(radiometry::MosaicParams{}), std::string());
        QCOMPARE(radiometry::validate(radiometry::GcpFitParams{}), std::string());
        QCOMPARE(radiometry::validate(radiometry::ReflectanceFitParams{}), std::string());
        QCOMPARE(radiometry::validate(radiometry::ApplyParams{}), std::string());
    }

    void outOfRangeValuesAreRefusedByTheirKey() {
        calib::DetectorFitParams d;
        d.triggerThreshold = -1;
        refusedNaming(calib::validate(d), "detector.trigger");
        d = {};
        d.outlierSigma = 2;  // 0 (off) or 3..1e6
        refusedNaming(calib::validate(d), "detector.outlier_sigma");
        d = {};
        d.relativeNoise = NAN;
        refusedNaming(calib::validate(d), "detector.rel_noise");
        d = {};  // the rule between two fields stays with the step
        d.triggerThreshold = 50;
        d.saturationLevel = 40;
        QVERIFY(calib::validate(d).find("exceed the trigger") != std::string::npos);
        // Through the step function too: an error, no fit.
        QVERIFY(!calib::fitDetectorArray({}, d).ok);

        // One value outside its row's range per step, and the key the message must name.
        const std::vector<std::pair<std::function<std::string()>, const char*>> cases = {
            {[] { calib::PointingCalibParams p; p.sigmaHorizontalM = 0; return calib::validate(p); }, "pointing.sigma_h"},
            {[] { calib::PointingCalibParams p; p.sigmaAttitudeRad = 0.2; return calib::validate(p); },  // 2e5 µrad > 1e5
             "pointing.sigma_attitude_urad"},
            {[] { calib::WaveformParams w; w.incidenceDeg = 61; return calib::validate(w); }, "waveform.incidence_deg"},
            {[] { calib::FeatureMatchParams m; m.thresholdM = 0; return calib::validate(m); }, "waveform.thred_h"},
            {[] { radiometry::MosaicParams m; m.minInliers = 3; return radiometry::validate(m); }, "mosaic.min_inliers"},
            {[] { radiometry::GcpFitParams g; g.collinearTolerance = 0.6; return radiometry::validate(g); },
             "gcp.collinear_tolerance"},
            {[] { radiometry::ReflectanceFitParams f; f.spectrometerPct = 100; return radiometry::validate(f); }, "vm_pct"},
            {[] { radiometry::ReflectanceFitParams f; f.minRegionPixels = 0; return radiometry::validate(f); },
             "min_region_pixels"},
            {[] { radiometry::ReflectanceFitParams f; f.minRegionFraction = 1.5; return radiometry::validate(f); },
             "min_region_fraction"},
            {[] { radiometry::ReflectanceFitParams f; f.dnMin = NAN; return radiometry::validate(f); }, "dn_min"},
            {[] { radiometry::ApplyParams a; a.dnMax = INFINITY; return radiometry::validate(a); }, "dn_max"},
        };
        for (const auto& [error, key] : cases) refusedNaming(error(), key);
        // The reflectance steps' rule between two rows: the DN range's ends in order.
        radiometry::ApplyParams a;
        a.dnMin = 500;
        a.dnMax = 400;
        QVERIFY(radiometry::validate(a).find("min < max") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestSchemaValidators)
#include "test_schema_validators.moc"
