#include "ui/footprint/footprint_export.hpp"

#include "core/footprint/batch.hpp"

namespace lwb::ui {

using namespace core::footprint;

bool writeFootprintReview(const std::vector<Shot>& shots, Method method, const QString& path, bool acceptedOnly,
                          QString* error, int* rows) {
    std::vector<BatchItem> items;
    items.reserve(shots.size());
    for (const Shot& s : shots) {
        BatchItem it;
        it.file = s.file.toStdString();
        it.time = s.time.toStdString();
        it.beam = s.beam.toStdString();
        it.camera = s.camera.toStdString();
        RoiReview rv;
        rv.overridden = s.overridden;
        rv.verdict = s.overrideVerdict;
        rv.note = s.note.toStdString();
        it.reviews.push_back(rv);
        if (!s.loadError.isEmpty()) {
            it.readError = s.loadError.toStdString();
        } else {
            FrameRoiResult fr;
            if (s.processed) {
                fr.result = s.result;
            } else {
                fr.result.ok = false;
                fr.result.error = "not processed yet (export again when the list is judged)";
            }
            fr.originX = s.origin.x();
            fr.originY = s.origin.y();
            it.rois.push_back(std::move(fr));
        }
        items.push_back(std::move(it));
    }
    FootprintCsvOptions o;
    o.review = true;
    o.acceptedOnly = acceptedOnly;
    std::string err;
    size_t written = 0;
    if (!writeFootprintCsv(path.toStdString(), items, method, &err, o, &written)) {
        *error = QString::fromStdString(err);
        return false;
    }
    if (rows) *rows = static_cast<int>(written);
    return true;
}

}  // namespace lwb::ui
