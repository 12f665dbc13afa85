#pragma once
// The SLR parameters an analyst tunes — screening (paper 004) and post-fit / normal points —
// declared once in one schema table (core/common/schema.hpp). Presets, sessions, the CLI's
// --config / --print-config / --set and the GUI's sliders all come from it.
#include "core/common/schema.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"

namespace lwb::core::slr {

struct SlrParams {
    ScreenParams screen;
    PostfitParams postfit;
};

/// The stages of a pass's run that a parameter row is tagged with (FieldInfo::stage): a change
/// reruns from the earliest stage it touches. Scale: the binary image and the scale search (every
/// screen.* row but one); Recovery: the cosine recovery at the chosen scale (screen.cosine_c);
/// Postfit: the trend, the rejection and the normal points (postfit.*).
enum SlrStage : int { kStageScale = 0, kStageRecovery = 1, kStagePostfit = 2 };

/// Keys "screen.cosine_c", "postfit.reject_sigma", ...; messages name them "slr.screen.cosine_c".
const Schema<SlrParams>& slrSchema();

}  // namespace lwb::core::slr
