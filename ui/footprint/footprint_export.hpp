#pragma once
// The footprint review table and the accepted shots as CSV, through the same core writer as
// `laserwb-cli footprint` (core/footprint/batch: writeFootprintCsv) with the review columns
// (time, beam, camera, auto_verdict, override, note). Written atomically.
#include <QString>
#include <vector>

#include "ui/footprint/footprint_controller.hpp"

namespace lwb::ui {

/// Every shot (acceptedOnly false) or the shots whose effective verdict is good and that have a
/// fit. False with *error (the file named) when it cannot be written; *rows (when given) is the
/// number of rows written.
bool writeFootprintReview(const std::vector<Shot>& shots, core::footprint::Method method, const QString& path,
                          bool acceptedOnly, QString* error, int* rows = nullptr);

}  // namespace lwb::ui
