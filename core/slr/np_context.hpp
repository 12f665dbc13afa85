#pragma once
// What the normal points of a CRD pass need besides the ranges: the laser fire rate (C1 record,
// for the return rate) and the station's latitude and longitude (from SINEX, for day or night
// by the Sun's elevation), filled into PostfitParams.
#include <string>
#include <vector>

#include "core/slr/crd.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/sinex.hpp"

namespace lwb::core::slr {

/// The nominal fire rate (Hz) of the C1 laser configuration record of the pass (v1 and v2:
/// field 6, "c1 0 ID TYPE WAVELENGTH FIRE_RATE ..."); the first C1 with a rate > 0. NaN when none.
double crdFireRateHz(const CrdPass& pass);

/// Fills params.fireRateHz (from C1, when the params have none), the normal-point bin length
/// (the ILRS missions table, when the params leave it at 0 and the satellite is listed), the
/// station's geodetic latitude and longitude (SINEX position of the pass's CDP pad at its
/// start; without a SINEX, the ILRS stations table) and the MJD of the day start, so that
/// postfit() judges day or night per bin. Returns notes for the summary (what was found or why
/// not); `sinex` may be null.
std::vector<std::string> fillNormalPointContext(const CrdPass& pass, int cdpPad, const SinexFile* sinex,
                                                PostfitParams* params);

}  // namespace lwb::core::slr
