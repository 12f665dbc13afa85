#include "core/slr/slr_params.hpp"

namespace lwb::core::slr {

namespace {

// The O-C of a pass (core/slr/oc.hpp): computed when the pass is opened, before any screening.
void addOcRows(Schema<SlrParams>& s) {
    using S = SlrParams;
    s.beginStage(kStageOc);
    s.choice("oc.refraction", LWB_FIELD(S, oc.refraction), {"none", "mendes_pavlis"},
             "tropospheric delay: Mendes & Pavlis (2004) zenith delay with the FCULa mapping, from the pass's "
             "type-20 meteorological records (a warning and none without them); none leaves the whole delay in the O-C");
    s.real("oc.wavelength_nm", LWB_FIELD(S, oc.wavelengthNm), "nm", {300, 2000}, {355, 1064},
           "laser wavelength for the refraction; null = the record's C0 configuration, else 532 with a warning")
        .specials = {{NAN, "from the record"}};
    s.boolean("oc.shapiro", LWB_FIELD(S, oc.shapiro), "add the relativistic (Shapiro) light-time delay of the Earth's field (a few mm)");
    s.real("oc.centre_of_mass_offset_m", LWB_FIELD(S, oc.targetComOffsetM), "m", {0, 10}, {0, 2},
           "centre of mass to reflector, one way; null = the CPF's H5 value when its positions are of the centre of "
           "mass (H2 flag 0), else 0")
        .specials = {{NAN, "from the CPF"}};
    auto& conv = s.real("oc.convergence_s", LWB_FIELD(S, oc.convergenceS), "s", {1e-15, 1e-9}, {1e-15, 1e-9},
                        "the light-time iteration stops when a leg changes by less than this");
    conv.uiLog = true;
    s.integer("oc.max_iterations", LWB_FIELD(S, oc.maxIterations), "", {2, 50}, {2, 20}, "light-time iterations per leg");
    s.integer("oc.lagrange_points", LWB_FIELD(S, oc.interpolation.points), "", {2, 20}, {4, 16},
              "Lagrange nodes of the CPF interpolation (ILRS practice: 8-10 for LEO at 1-5 min steps)");
    s.integer("oc.cpf_direction", LWB_FIELD(S, oc.interpolation.direction), "", {0, 2}, {0, 2},
              "which CPF position records: 0 the common epoch, 1 or 2 for files that have them");
    s.integer("oc.own_trend_degree", LWB_FIELD(S, ownTrend.degree), "", {1, 20}, {2, 8},
              "without a prediction: degree of the robust polynomial of the squared time of flight (lowered for "
              "short passes: max((records-1)/4, 2))");
    s.real("oc.own_trend_huber_k", LWB_FIELD(S, ownTrend.huberK), "sigma", {0.5, 10}, {1, 3},
           "without a prediction: the trend's Huber constant, in robust standard deviations");
    s.integer("oc.own_trend_max_iterations", LWB_FIELD(S, ownTrend.maxIterations), "", {1, 500}, {5, 100},
              "without a prediction: the trend's reweighting iterations");
    s.integer("oc.own_trend_min_points", LWB_FIELD(S, ownTrend.minPoints), "", {3, 1000000}, {3, 20},
              "without a prediction: fewer usable records is an error");
}

}  // namespace

const Schema<SlrParams>& slrSchema() {
    static const Schema<SlrParams> schema = [] {
        using S = SlrParams;
        Schema<S> s("slr");
        s.beginStage(kStageScale);
        const SpecialValue autoValue{0, "auto"};
        s.boolean("screen.automatic", LWB_FIELD(S, screen.automatic),
                  "automatic mode: mag_t, mag_oc, area_limit and connectivity left at 0 (auto) are chosen from the data (multi-scale search)");
        auto& magT = s.real("screen.mag_t", LWB_FIELD(S, screen.magT), "px/s", {0, 1e15, true, false}, {1e-3, 1e4},
                            "pixels per second of epoch (paper: 10 conventional, 1 diffuse); 0 = auto");
        magT.specials = {autoValue};
        magT.uiLog = true;
        auto& magOc = s.real("screen.mag_oc", LWB_FIELD(S, screen.magOc), "px/s", {0, 1e18, true, false}, {1e6, 1e12},
                             "pixels per second of O-C (paper: 1e10 conventional, 1e7 diffuse); 0 = auto");
        magOc.specials = {autoValue};
        magOc.uiLog = true;
        s.integer("screen.area_limit", LWB_FIELD(S, screen.areaLimit), "px", {1, 1000000}, {1, 50},
                  "regions with at least this area are candidates (step 3); 0 = auto")
            .specials = {autoValue};
        s.integer("screen.connectivity", LWB_FIELD(S, screen.connectivity), "", {4, 8}, {4, 8},
                  "4 for high echo rates, 8 for low (paper 004); 0 = auto")
            .specials = {autoValue};
        auto& c = s.real("screen.cosine_c", LWB_FIELD(S, screen.cosineC), "", {0.5, 1, false, true}, {0.9, 0.999},
                         "cosine constant C of the recovery step (paper 004 eq. 3: 0.9 < C < 1; smaller lets noise in)");
        c.decimals = 4;
        c.stage = kStageRecovery;
        s.integer("screen.slope_neighbours", LWB_FIELD(S, screen.slopeNeighbours), "", {2, 64}, {4, 16},
                  "step 4: slopes from each candidate piece to its k nearest pieces");
        s.real("screen.slope_bin_deg", LWB_FIELD(S, screen.slopeBinDeg), "deg", {0.25, 30}, {0.5, 5},
               "step 4: bin width of the line-angle histogram");
        s.real("screen.slope_peak_fraction", LWB_FIELD(S, screen.slopePeakFraction), "", {0, 1, true, true}, {0.1, 0.5},
               "step 4: the dominant range is the run of bins holding at least this fraction of the peak");
        s.real("screen.slope_agree_fraction", LWB_FIELD(S, screen.slopeAgreeFraction), "", {0, 1, true, false}, {0.2, 0.6},
               "step 4: a candidate is on the line when this share of its slopes is in range (paper: 1/3)");
        s.real("screen.max_slope_range_deg", LWB_FIELD(S, screen.maxSlopeRangeDeg), "deg", {2, 180}, {10, 90},
               "step 4: the dominant range is at most this wide");
        s.integer("screen.slope_block_regions", LWB_FIELD(S, screen.slopeBlockRegions), "", {10, 100000000}, {50, 1000},
                  "step 4: pieces per time block with its own histogram (curved tracks); 0 = one histogram (paper)")
            .specials = {{0, "one histogram"}};
        s.integer("screen.piece_rows", LWB_FIELD(S, screen.pieceRows), "px", {0, 1000000}, {0, 32},
                  "steps 4-5: regions cut into pieces of this many rows; 0 = whole regions (paper)");
        s.real("screen.recovery_gap_factor", LWB_FIELD(S, screen.recoveryGapFactor), "", {0, 1e6}, {0, 10},
               "step 5: anchors at most this many typical spacings apart; 0 = no limit (paper)");
        s.real("screen.area_tolerance", LWB_FIELD(S, screen.areaTolerance), "", {0, 0.5, true, false}, {1e-5, 1e-2},
               "automatic area limit: share of pure-noise regions allowed to reach it")
            .uiLog = true;
        s.integer("screen.auto_max_points", LWB_FIELD(S, screen.autoMaxPoints), "", {1000, 10000000}, {10000, 100000},
                  "automatic mode scores scales on at most this many points");
        s.integer("screen.refine_rounds", LWB_FIELD(S, screen.refineRounds), "", {0, 3}, {0, 3},
                  "screening rounds on the O-C flattened by the accepted track's trend (0 in the paper's fixed procedure)");
        s.real("screen.sparse_rate_below", LWB_FIELD(S, screen.sparseRateBelow), "1/s", {0, 1e7}, {0, 200},
               "passes with fewer returns per second get the sparse-pass ladders and refinement; 0 = always");
        s.boolean("screen.follow_track", LWB_FIELD(S, screen.followTrack),
                  "sparse passes: follow the track from the accepted pieces (ends, gaps, pieces beyond gaps)");
        s.boolean("screen.accept_floorless", LWB_FIELD(S, screen.acceptFloorless),
                  "a pass with no noise floor (filtered; robust sigma <= 1 ns, <= 2 % beyond 5 sigma) "
                  "keeps every point within 5 sigma of its track");
        addOcRows(s);
        s.beginStage(kStagePostfit);
        s.integer("postfit.degree", LWB_FIELD(S, postfit.degree), "", {0, 30}, {2, 15},
                  "trend polynomial degree (Legendre, per segment); the largest tried when auto_degree");
        s.boolean("postfit.auto_degree", LWB_FIELD(S, postfit.autoDegree),
                  "choose each segment's model by BIC (degrees 0..degree, cubic splines); false = degree as given");
        s.real("postfit.split_gap_s", LWB_FIELD(S, postfit.splitGapS), "s", {-1, 86400}, {10, 300},
               "split the trend at gaps longer than this; 0 = auto (3 bin lengths, at least 20 s); < 0 = one trend")
            .specials = {{0, "auto"}};
        s.real("postfit.gross_sigma", LWB_FIELD(S, postfit.grossSigma), "sigma", {3, 1000}, {5, 30},
               "reject points this many robust sigma off the local track before the fit; 0 = off")
            .specials = {{0, "off"}};
        s.real("postfit.reject_sigma", LWB_FIELD(S, postfit.rejectSigma), "sigma", {1, 10}, {2, 4},
               "k of the k-sigma rejection: 2.5 single-photon, 3 multi-photon (ILRS); 0 = off")
            .specials = {{0, "off"}};
        s.boolean("postfit.noise_band", LWB_FIELD(S, postfit.noiseBand),
                  "narrow the k-sigma band where the noise beside the track is measurable: the band of the best "
                  "expected F1 (the signal's sigma with that noise taken out), never wider than k sigma");
        s.boolean("postfit.take_band", LWB_FIELD(S, postfit.takeBand),
                  "take the points the screening left out that lie within the final band about the trend "
                  "(inside its segments), and fit again with them");
        s.integer("postfit.max_iterations", LWB_FIELD(S, postfit.maxIterations), "", {1, 1000}, {5, 50}, "fit-reject iterations");
        s.real("postfit.bin_length_s", LWB_FIELD(S, postfit.binLengthS), "s", {0.1, 86400}, {5, 300},
               "normal-point bin length; 0 = from the altitude (ILRS table)")
            .specials = {{0, "from altitude"}};
        s.real("postfit.altitude_km", LWB_FIELD(S, postfit.altitudeKm), "km", {0, 1e6}, {300, 25000},
               "satellite altitude for the normal-point bin; 0 = unknown (from the pass when it can be)");
        s.integer("postfit.min_points", LWB_FIELD(S, postfit.minPointsPerBin), "", {1, 1000000}, {1, 20},
                  "points a bin needs for a normal point; 0 = ILRS minimum (6 by day, 3 by night)")
            .specials = {{0, "ILRS minimum"}};
        s.choice("postfit.day_night", LWB_FIELD(S, postfit.dayNight), {"auto", "day", "night"},
                 "day or night for the ILRS minimum of points per normal-point bin (6 by day, 3 by night): auto = from "
                 "the Sun at the station bin by bin when the station is known (SINEX), else the day minimum");
        // Files written before day_night held a boolean "daylight", false unless set: true is a
        // day pass, false was "not said" (the day minimum applied when the station was unknown).
        s.legacy([](Json& j) {
            if (!j.contains("postfit") || !j["postfit"].is_object() || !j["postfit"].contains("daylight")) return;
            Json& pf = j["postfit"];
            if (pf["daylight"].is_boolean() && !pf.contains("day_night")) pf["day_night"] = pf["daylight"].get<bool>() ? "day" : "auto";
            if (pf["daylight"].is_boolean()) pf.erase("daylight");
        });
        s.real("postfit.fire_rate_hz", LWB_FIELD(S, postfit.fireRateHz), "Hz", {0, 1e9, true, false}, {1, 10000},
               "laser fire rate for the normal points' return rate; 0 = unknown")
            .specials = {{0, "unknown"}};
        s.boolean("postfit.normal_points", LWB_FIELD(S, postfit.normalPoints), "form normal points (off: trend and statistics only)");
        s.rule(
            [](const S& p) -> std::string {
                const ScreenParams& q = p.screen;
                if (q.connectivity != 0 && q.connectivity != 4 && q.connectivity != 8)
                    return "screen.connectivity must be 4, 8 or 0 (auto), not " + std::to_string(q.connectivity);
                if (q.automatic) return {};
                if (q.magT == 0) return "screen.mag_t not given and the automatic mode is off";
                if (q.magOc == 0) return "screen.mag_oc not given and the automatic mode is off";
                if (q.areaLimit == 0) return "screen.area_limit not given (0) and the automatic mode is off";
                if (q.connectivity == 0) return "screen.connectivity not given and the automatic mode is off";
                return {};
            },
            "screen.");
        return s;
    }();
    return schema;
}

}  // namespace lwb::core::slr
