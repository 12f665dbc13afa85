#include "core/sim/calib_sim.hpp"

#include <cmath>

#include "core/calib/geodesy.hpp"
#include "core/common/rng.hpp"

namespace lwb::core::sim {

using namespace calib;

std::vector<BeamDesign> gf7Beams() {
    BeamDesign b1, b2;
    b1.id = 1;
    b1.alphaRad = 0.7 * kDeg;
    b1.betaRad = 90 * kDeg;
    b2.id = 2;
    b2.alphaRad = 0.7 * kDeg;
    b2.betaRad = -90 * kDeg;
    return {b1, b2};
}

namespace {

Eigen::Matrix3d smallRotation(const Eigen::Vector3d& w) {
    const double t = w.norm();
    if (t < 1e-300) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(t, w / t).toRotationMatrix();
}

// Range along the ECEF unit ray d from origin o at which the geodetic height equals h.
double rangeToHeight(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double h) {
    const Geodetic g0 = ecefToGeodetic(o);
    double rho = g0.h - h;
    for (int i = 0; i < 20; ++i) {
        const Eigen::Vector3d p = o + rho * d;
        const Geodetic g = ecefToGeodetic(p);
        const Eigen::Vector3d up = ecefToEnuRotation(g.latRad, g.lonRad).row(2).transpose();
        const double step = (g.h - h) / std::max(1e-6, -d.dot(up));
        rho += step;
        if (std::fabs(step) < 1e-7) break;
    }
    return rho;
}

}  // namespace

CalibSimulation simulateCalibration(const CalibSimParams& p, uint64_t seed) {
    CalibSimulation s;
    s.beams = gf7Beams();
    for (int k = 0; k < 2; ++k) {
        s.dAlpha[k] = p.dAlpha[k];
        s.dBeta[k] = p.dBeta[k];
        s.dRho[k] = p.dRho[k];
    }
    s.matchingParams.sigmaHorizontalM = p.sigmaHorizontalM;
    s.matchingParams.sigmaVerticalM = p.sigmaVerticalM;
    s.matchingParams.sigmaRangeM = p.sigmaRangeM;
    s.matchingParams.sigmaAttitudeRad = p.sigmaAttitudeRad;
    s.matchingParams.sigmaOrbitM = p.sigmaOrbitM;
    s.matchingParams.model = p.dualBeam ? CalibModel::DualBeam : CalibModel::SingleBeam;
    Rng rng(seed);
    const double lat0 = p.siteLatDeg * kDeg, lon0 = p.siteLonDeg * kDeg;
    const LocalFrame site(lat0, lon0, p.siteHeightM);
    for (int pass = 0; pass < p.passes; ++pass) {
        // Ground track: heading from the inclination (ascending or descending), offset across.
        const double sinAz = std::clamp(std::cos(p.inclinationDeg * kDeg) / std::cos(lat0), -1.0, 1.0);
        double az = std::asin(sinAz);
        if (rng.uniform() < 0.5) az = M_PI - az;  // descending
        const Eigen::Vector3d alongEnu(std::sin(az), std::cos(az), 0);
        const Eigen::Vector3d rightEnu(std::cos(az), -std::sin(az), 0);  // along × up
        const double cross = rng.uniform(-p.crossTrackSpreadM, p.crossTrackSpreadM);
        const double along = rng.uniform(-2000, 2000);
        const Eigen::Vector3d nadirEnu = cross * rightEnu + along * alongEnu;
        const Geodetic nadir = ecefToGeodetic(site.toEcef(nadirEnu));
        const Eigen::Vector3d satTrue = geodeticToEcef(nadir.latRad, nadir.lonRad, p.altitudeM);
        const Eigen::Matrix3d enu = ecefToEnuRotation(nadir.latRad, nadir.lonRad);
        const Eigen::Vector3d x = enu.transpose() * alongEnu, z = -enu.row(2).transpose();
        const Eigen::Vector3d y = z.cross(x);
        Eigen::Matrix3d att;
        att.col(0) = x;
        att.col(1) = y;
        att.col(2) = z;
        const double bmax = p.attitudeBiasMaxDeg * kDeg;
        att = att * smallRotation({rng.uniform(-bmax, bmax), rng.uniform(-bmax, bmax), rng.uniform(-bmax, bmax)});
        // Knowledge errors shared by the pass's beams.
        const Eigen::Matrix3d attKnown =
            att * smallRotation({rng.normal(0, p.sigmaAttitudeRad), rng.normal(0, p.sigmaAttitudeRad),
                                 rng.normal(0, p.sigmaAttitudeRad)});
        // Draws as named values: the order of a constructor's arguments is unspecified (GCC takes
        // them right to left, clang left to right), and a simulator must give the same data from
        // every compiler. The order below is the one the GCC builds always had.
        const double orbitZ = rng.normal(0, p.sigmaOrbitM), orbitY = rng.normal(0, p.sigmaOrbitM),
                     orbitX = rng.normal(0, p.sigmaOrbitM);
        const Eigen::Vector3d satKnown = satTrue + Eigen::Vector3d(orbitX, orbitY, orbitZ);
        const int nBeams = p.dualBeam ? 2 : 1;
        for (int k = 0; k < nBeams; ++k) {
            const BeamDesign& b = s.beams[k];
            const Eigen::Vector3d uTrue = att * bodyPointing(b, p.dAlpha[k], p.dBeta[k]);
            const Eigen::Vector3d origin = satTrue + att * b.offsetBodyM;
            const double h = p.siteHeightM + rng.uniform(-p.terrainSpreadM, p.terrainSpreadM);
            const double rhoTrue = rangeToHeight(origin, uTrue, h);
            const Eigen::Vector3d gTrue = origin + rhoTrue * uTrue;
            ControlPoint c;
            c.id = "p" + std::to_string(pass + 1) + "b" + std::to_string(b.id);
            c.beam = b.id;
            c.shot.satEcef = satKnown;
            c.shot.bodyToEcef = Eigen::Quaterniond(attKnown).normalized();
            c.shot.rangeM = rhoTrue - p.dRho[k] + rng.normal(0, p.sigmaRangeM);
            const Geodetic g = ecefToGeodetic(gTrue);
            const Eigen::Matrix3d genu = ecefToEnuRotation(g.latRad, g.lonRad);
            const double up = rng.normal(0, p.sigmaVerticalM), north = rng.normal(0, p.sigmaHorizontalM),
                         east = rng.normal(0, p.sigmaHorizontalM);  // (order: see satKnown)
            const Eigen::Vector3d noise(east, north, up);
            c.groundEcef = gTrue + genu.transpose() * noise;
            s.points.push_back(c);
            s.trueGround.push_back(gTrue);
        }
    }
    return s;
}

DetectorSimulation simulateDetectorArray(const DetectorSimParams& p, uint64_t seed) {
    DetectorSimulation s;
    Rng rng(seed);
    double e0 = rng.uniform(-p.centreSpreadM, p.centreSpreadM), n0 = rng.uniform(-p.centreSpreadM, p.centreSpreadM);
    if (std::isfinite(p.centreE)) e0 = p.centreE;
    if (std::isfinite(p.centreN)) n0 = p.centreN;
    const double ratio = rng.uniform(1.0, std::max(1.0, p.axisRatioMax));
    const double theta = rng.uniform(-M_PI / 2, M_PI / 2);
    // σ_major·σ_minor = sigmaM² keeps the footprint area.
    const double smaj = p.sigmaM * std::sqrt(ratio), smin = p.sigmaM / std::sqrt(ratio);
    const double c = std::cos(theta), sn = std::sin(theta);
    const double see = smaj * smaj * c * c + smin * smin * sn * sn, snn = smaj * smaj * sn * sn + smin * smin * c * c;
    const double sen = (smaj * smaj - smin * smin) * c * sn;
    const double det = see * snn - sen * sen;
    GaussSurface& t = s.truth;
    t.amplitude = p.amplitude;
    t.e0 = e0;
    t.n0 = n0;
    t.a = snn / det;
    t.b = -sen / det;
    t.c = see / det;
    t.background = p.background;
    t.sigmaMajor = smaj;
    t.sigmaMinor = smin;
    t.orientationRad = theta;
    DetectorArray& arr = s.array;
    arr.geographic = p.geographic;
    if (p.geographic) {
        arr.originLatDeg = p.originLatDeg;
        arr.originLonDeg = p.originLonDeg;
        arr.originH = p.heightM;
    }
    int id = 0;
    for (int r = 0; r < p.rows; ++r)
        for (int col = 0; col < p.columns; ++col) {
            Detector d;
            d.id = "D" + std::to_string(++id);
            d.e = (col - 0.5 * (p.columns - 1)) * p.spacingM;
            d.n = (r - 0.5 * (p.rows - 1)) * p.spacingM;
            d.h = p.heightM;
            const double truth = evalSurface(t, d.e, d.n);
            const double relNoise = rng.normal(0, p.relativeNoise * std::fabs(truth)), floorNoise = rng.normal(0, p.noiseFloor);
            double e = truth + relNoise + floorNoise;
            const bool dead = p.deadFraction > 0 && rng.uniform() < p.deadFraction;
            bool clipped = false;
            if (dead) {
                e = 0;
            } else if (p.saturationLevel > 0 && e >= p.saturationLevel) {
                e = p.saturationLevel;
                clipped = true;
            }
            d.saturated = p.flagSaturated ? (clipped ? 1 : 0) : -1;
            if (p.fullReport) {
                d.triggered = -1;
                d.energy = e;
            } else if (!dead && e > p.triggerThreshold) {
                d.triggered = 1;
                d.energy = e;
            } else {
                if (!p.listUntriggered) continue;
                d.triggered = 0;
                d.energy = NAN;
                if (p.flagSaturated) d.saturated = 0;
            }
            arr.detectors.push_back(d);
        }
    return s;
}

DetectorSimParams drawDetectorFieldCase(uint64_t seed) {
    Rng rng(seed);
    DetectorSimParams p;
    p.rows = 17;
    p.columns = 9;
    p.spacingM = 5;
    p.sigmaM = rng.uniform(13, 17) / 4;  // 1/e² diameter = 4σ
    p.axisRatioMax = 1.3;
    p.amplitude = 1000;
    p.relativeNoise = 0;
    p.noiseFloor = rng.uniform(0.02, 0.05) * p.amplitude;
    const double halfE = 0.5 * (p.columns - 1) * p.spacingM - 5, halfN = 0.5 * (p.rows - 1) * p.spacingM - 5;
    p.centreE = rng.uniform(-halfE, halfE);
    p.centreN = rng.uniform(-halfN, halfN);
    p.fullReport = rng.uniform() < 0.5;
    p.background = p.fullReport ? rng.uniform(0, 0.03) * p.amplitude : 0;
    p.triggerThreshold = p.background + 3 * p.noiseFloor;
    p.listUntriggered = rng.uniform() < 0.5;
    p.deadFraction = 0.02;
    p.saturationLevel = rng.uniform() < 0.3 ? rng.uniform(0.6, 0.95) * p.amplitude : 0;
    p.flagSaturated = rng.uniform() < 0.5;
    return p;
}

WaveformSimulation simulateWaveform(const WaveformSimParams& p, uint64_t seed) {
    WaveformSimulation s;
    Rng rng(seed);
    s.deltaTNs = 2 * p.heightM * std::cos(p.incidenceDeg * kDeg) / kSpeedOfLight * 1e9;
    const double t1 = p.firstReturnNs, t2 = p.firstReturnNs + s.deltaTNs;
    for (int i = 0; i < p.samples; ++i) {
        const double t = i * p.sampleIntervalNs;
        const double u1 = (t - t1) / p.sigmaNs, u2 = (t - t2) / p.sigmaNs;
        const double v = p.baseline + p.amplitudeTop * std::exp(-0.5 * u1 * u1) +
                         p.amplitudeGround * std::exp(-0.5 * u2 * u2) + rng.normal(0, p.noise);
        s.waveform.timeNs.push_back(t);
        s.waveform.amplitude.push_back(v);
    }
    return s;
}

}  // namespace lwb::core::sim
