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

/// Keys "screen.cosine_c", "postfit.reject_sigma", ...; messages name them "slr.screen.cosine_c".
const Schema<SlrParams>& slrSchema();

}  // namespace lwb::core::slr
