#pragma once
// Shared by the footprint accuracy tests: the simulator's doubtful cases as test rows, and the
// verdict counts of the default method over them.
#include <QtTest>

#include "core/sim/footprint_eval.hpp"

namespace lwbtest {

/// Rows "scene" (int) and "target" (mean radial error, px) for the four classes (issue 14).
inline void addClassTargetRows() {
    using lwb::core::sim::Scene;
    QTest::addColumn<int>("scene");
    QTest::addColumn<double>("target");
    QTest::newRow("weak <= 0.10 px") << int(Scene::Weak) << 0.10;
    QTest::newRow("moderate <= 0.14 px") << int(Scene::Moderate) << 0.14;
    QTest::newRow("strong <= 0.20 px") << int(Scene::Strong) << 0.20;
    QTest::newRow("night <= 0.05 px") << int(Scene::Night) << 0.05;
}

/// Rows "spotCase" (int) for each doubtful case of the simulator.
inline void addDoubtfulCaseRows() {
    using lwb::core::sim::SpotCase;
    QTest::addColumn<int>("spotCase");
    QTest::newRow("no spot") << int(SpotCase::NoSpot);
    QTest::newRow("saturated under cloud") << int(SpotCase::Saturated);
    QTest::newRow("double spot") << int(SpotCase::DoubleSpot);
    QTest::newRow("edge") << int(SpotCase::Edge);
    QTest::newRow("elongated") << int(SpotCase::Elongated);
}

struct CaseCounts {
    int n = 0, good = 0, rejected = 0;
};

/// The default method over `perClass` shots of one case on each day/night class (seed 2).
inline CaseCounts doubtfulCaseCounts(lwb::core::sim::SpotCase c, int perClass, lwb::core::sim::GroundSource g) {
    using namespace lwb::core::sim;
    MethodVariant def;
    findVariant("gauss", &def);
    EvalParams ep;
    ep.countPerScene = perClass;
    ep.seed = 2;
    ep.sim.ground = g;
    ep.spotCase = c;
    ep.scenes = {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night};
    CaseCounts k;
    for (const auto& s : evaluateFootprint(ep, {def})) {
        k.good += s.good;
        k.rejected += s.rejected;
        k.n += s.n;
    }
    return k;
}

}  // namespace lwbtest
