#pragma once
// The SLR parameters an analyst tunes — the O-C computation (light time, refraction, the own-TOF
// trend without a prediction), screening (paper 004) and post-fit / normal points — declared
// once in one schema table (core/common/schema.hpp). Presets, sessions, the CLI's
// --config / --print-config / --set and the GUI's sliders all come from it.
#include "core/common/schema.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"

namespace lwb::core::slr {

struct SlrParams {
    OcParams oc;              ///< the O-C from the prediction (oc.*)
    TrendOcParams ownTrend;   ///< the O-C from the pass's own TOF trend, without a prediction (oc.own_trend_*)
    ScreenParams screen;
    PostfitParams postfit;
};

/// The stages of a pass's run that a parameter row is tagged with (FieldInfo::stage): a change
/// reruns from the earliest stage it touches. O-C: the pass's O-C, computed when the pass is
/// opened (oc.*: the pass is opened again); Scale: the binary image and the scale search (every
/// screen.* row but one); Recovery: the cosine recovery at the chosen scale (screen.cosine_c);
/// Postfit: the trend, the rejection and the normal points (postfit.*).
enum SlrStage : int { kStageOc = 0, kStageScale = 1, kStageRecovery = 2, kStagePostfit = 3 };

/// Keys "screen.cosine_c", "postfit.reject_sigma", ...; messages name them "slr.screen.cosine_c".
const Schema<SlrParams>& slrSchema();

}  // namespace lwb::core::slr
