#include "core/footprint/batch.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::footprint {

BatchResult runFootprintBatch(const std::vector<std::string>& files, const BatchParams& params, Feedback* fb,
                              const BatchItemFn& onItem) {
    BatchResult out;
    out.items.resize(files.size());
    std::atomic<size_t> next{0}, done{0};
    std::mutex cbMutex;
    const size_t total = files.size();
    auto worker = [&]() {
        while (true) {
            if (cancelled(fb)) return;
            const size_t i = next.fetch_add(1);
            if (i >= total) return;
            BatchItem& item = out.items[i];
            item.file = files[i];
            try {
                const ImageReadResult img = readFrame(files[i], params.read);
                if (!img.ok)
                    item.readError = img.error;
                else
                    item.rois = processFrame(img.image, params.footprint, params.centres);
            } catch (const std::exception& e) {  // e.g. out of memory on a huge frame: this item only
                item.rois.clear();
                item.readError = files[i] + ": " + e.what();
            }
            const size_t d = ++done;
            std::lock_guard<std::mutex> lock(cbMutex);
            if (onItem) onItem(i, item);
            if (fb && (d == total || d % 64 == 0)) fb->setProgress(static_cast<double>(d) / total);
        }
    };
    int n = params.threads > 0 ? params.threads : static_cast<int>(std::thread::hardware_concurrency());
    n = std::max(1, std::min<int>(n, static_cast<int>(std::max<size_t>(total, 1))));
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    out.cancelled = cancelled(fb) && done < total;
    if (out.cancelled) out.items.resize(0);
    for (const auto& it : out.items)
        if (!it.readError.empty()) ++out.readErrors;
    return out;
}

std::string footprintCsvHeader(const std::vector<std::string>& extra) {
    std::string h = "file,x,y,verdict,reasons,method,noise_class,sigma_x,sigma_y,axis_ratio,tilt_deg,major_axis_px,"
                    "mse,snr,crlb_px,roi,uncertainty_px,eccentricity,area_px,amplitude_dn,background_dn,roi_x0,roi_y0";
    for (const auto& name : extra) h += "," + csvEscape(name);
    return h + "\n";
}

namespace {
std::string num(double v, int decimals) { return std::isfinite(v) ? formatFixed(v, decimals) : ""; }
std::string sci(double v) { return std::isfinite(v) ? formatDouble(v, 4) : ""; }
std::string joinReasons(const std::vector<std::string>& r) {
    std::string s;
    for (size_t i = 0; i < r.size(); ++i) s += (i ? "; " : "") + r[i];
    return s;
}
}  // namespace

std::string footprintCsvRows(const BatchItem& item, Method method, const std::vector<std::string>& extra) {
    std::string end;  // the extra columns and the line end
    for (const auto& v : extra) end += "," + csvEscape(v);
    end += "\n";
    std::string out;
    const std::string file = csvEscape(item.file);
    if (!item.readError.empty()) {
        out += file + ",,,rejected," + csvEscape("unreadable: " + item.readError) + "," + methodName(method) +
               ",,,,,,,,,,0,,,,,,," + end;
        return out;
    }
    for (size_t k = 0; k < item.rois.size(); ++k) {
        const FrameRoiResult& fr = item.rois[k];
        const FootprintResult& r = fr.result;
        if (!r.ok) {
            out += file + ",,,rejected," + csvEscape(r.error) + "," + methodName(method) + ",,,,,,,,,," +
                   std::to_string(k) + ",,,,,,," + end;
            continue;
        }
        const SpotFit& f = r.fit;
        const bool has = f.ok && r.verdict != Verdict::Rejected;
        out += file + ",";
        out += (has ? num(f.x + fr.originX, 4) : "") + "," + (has ? num(f.y + fr.originY, 4) : "") + ",";
        out += std::string(verdictName(r.verdict)) + "," + csvEscape(joinReasons(r.reasons)) + ",";
        out += std::string(methodName(r.method)) + "," + noiseClassName(r.background.noiseClass) + ",";
        if (f.ok) {
            out += num(f.sigmaX, 4) + "," + num(f.sigmaY, 4) + "," + num(f.axisRatio, 4) + "," +
                   num(f.tiltRad * 180 / M_PI, 3) + "," + num(f.majorAxisPx, 3) + "," + sci(f.mse) + "," +
                   num(f.snr, 2) + "," + num(r.crlbPx, 5) + ",";
        } else {
            out += ",,,,,,,,";
        }
        out += std::to_string(k) + ",";
        if (f.ok)
            out += num(f.uncertaintyPx, 5) + "," + num(f.eccentricity, 4) + "," + num(f.areaPx, 0) + "," +
                   num(f.amplitude, 1) + "," + num(f.background, 1);
        else
            out += ",,,," + num(r.background.level, 1);
        out += "," + std::to_string(fr.originX) + "," + std::to_string(fr.originY) + end;
    }
    return out;
}

bool writeFootprintCsv(const std::string& path, const std::vector<BatchItem>& items, Method method,
                       std::string* error, const FootprintCsvExtra* extra) {
    if (extra && extra->values.size() != items.size()) {
        *error = "footprint report: " + std::to_string(extra->values.size()) + " rows of extra columns for " +
                 std::to_string(items.size()) + " items";
        return false;
    }
    if (extra)
        for (size_t i = 0; i < items.size(); ++i)
            if (extra->values[i].size() != extra->names.size()) {
                *error = "footprint report: item " + std::to_string(i) + " has " + std::to_string(extra->values[i].size()) +
                         " extra values for " + std::to_string(extra->names.size()) + " extra columns";
                return false;
            }
    AtomicFile f(path);
    if (!f.ok()) {
        *error = f.error();
        return false;
    }
    static const std::vector<std::string> none;
    f.stream() << footprintCsvHeader(extra ? extra->names : none);
    for (size_t i = 0; i < items.size(); ++i) f.stream() << footprintCsvRows(items[i], method, extra ? extra->values[i] : none);
    if (!f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

}  // namespace lwb::core::footprint
