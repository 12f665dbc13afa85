#include "core/footprint/footprint_run.hpp"

#include <algorithm>

#include "core/common/folder.hpp"
#include "core/footprint/roi.hpp"

namespace lwb::core::footprint {

namespace {

bool endsWithCsv(const std::string& path) {
    if (path.size() < 4) return false;
    std::string end = path.substr(path.size() - 4);
    std::transform(end.begin(), end.end(), end.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return end == ".csv";
}

// The regular files of a folder that are not hidden, sorted by name (none when it cannot be read).
std::vector<std::string> folderFiles(const std::string& folder) {
    std::vector<std::string> out;
    listFolder(folder, &out, nullptr);
    return out;
}

// The workbench's reading of what was picked: frames, folders and (when no frame is among them)
// shot lists; every other file set aside and listed.
bool gatherSettingAside(const std::vector<std::string>& inputs, FootprintSetup* s, std::string* error) {
    bool anyFrame = false;
    for (const auto& in : inputs) anyFrame |= isFolder(in) || isFrameFile(in);
    std::vector<std::string> kept;
    for (const auto& in : inputs) {
        const bool folder = isFolder(in);
        const bool list = endsWithCsv(in) && !anyFrame;
        if (!folder && !isFrameFile(in) && !list && pathExists(in)) {
            s->setAside.push_back(in);
            continue;
        }
        if (folder)  // its files that are not frames are left out too, and listed
            for (const auto& f : folderFiles(in))
                if (!isFrameFile(f)) s->setAside.push_back(f);
        kept.push_back(in);
    }
    return expandShots(kept, &s->shots, error);
}

}  // namespace

bool resolveFootprintParams(const FootprintSources& src, FootprintParams* out, FootprintError* error) {
    FootprintParams p;
    std::string err;
    if (!src.configFile.empty()) {
        const JsonParseResult doc = readJsonFile(src.configFile);
        if (!doc.ok || !footprintParamsFromJson(doc.value, &p, &err, &doc)) {
            *error = {doc.ok ? err : doc.error, false};
            return false;
        }
    }
    if (!src.config.is_null() && !footprintParamsFromJson(src.config, &p, &err)) {
        *error = {err, true};
        return false;
    }
    if (!src.preset.empty() && !applyPreset(src.preset, &p)) {
        *error = {"--preset must be wu2021 or yao2021, not \"" + src.preset + "\"", true};
        return false;
    }
    for (const ParamSetting& s : src.set) {
        if (!footprintSchema().setFromText(&p, s.key, s.value, &err)) {
            *error = {(s.label.empty() ? s.key + "=" + s.value : s.label) + ": " + err, true};
            return false;
        }
        if (s.key == "roi.size") p.roi.sizeExplicit = true;  // (roi.size_strict: the size asked for)
    }
    if (const std::string e = validate(p); !e.empty()) {
        *error = {e, true};
        return false;
    }
    *out = p;
    return true;
}

bool resolveBatchParams(const FootprintSources& src, BatchParams* out, FootprintError* error) {
    BatchParams bp;
    if (!resolveFootprintParams(src, &bp.footprint, error)) return false;
    bp.centres = src.centres;
    bp.read = src.read;
    bp.threads = src.threads;
    *out = std::move(bp);
    return true;
}

bool setUpFootprintRun(const FootprintSources& src, FootprintSetup* out, FootprintError* error) {
    FootprintSetup s;
    if (!resolveBatchParams(src, &s.params, error) || !gatherShots(src, &s, error)) return false;
    *out = std::move(s);
    return true;
}

bool gatherShots(const FootprintSources& src, FootprintSetup* out, FootprintError* error) {
    FootprintSetup& s = *out;
    s.shots.clear();
    s.setAside.clear();
    s.unmatched = 0;
    if (src.inputs.empty()) {
        *error = {"no input files, folders or shot lists", true};
        return false;
    }
    std::string err;
    if (!(src.setAsideOthers ? gatherSettingAside(src.inputs, &s, &err)
                             : expandShots(src.inputs, &s.shots, &err, src.keepGoing))) {
        *error = {err, false};
        return false;
    }
    if (s.shots.empty()) {
        *error = {"the inputs hold no image files (png, tif, tiff, pgm, raw, bin)", false};
        return false;
    }
    if (!src.metadata.empty()) {
        const ShotListResult md = readShotList(src.metadata);
        if (!md.ok || !applyFrameMetadata(md, &s.shots, &s.unmatched, &err)) {
            *error = {"--metadata: " + (md.ok ? err : md.error), false};
            return false;
        }
    }
    return true;
}

std::vector<ShotRoi> cutShotRois(const cv::Mat& frame, const ShotSpec& shot, const BatchParams& params) {
    std::vector<RoiParams> where;
    if (shot.hasCenter || !params.centres.empty()) {
        const std::vector<cv::Point2d> centres =
            shot.hasCenter ? std::vector<cv::Point2d>{{shot.centerX, shot.centerY}} : params.centres;
        for (const auto& c : centres) {
            RoiParams rp = params.footprint.roi;
            rp.hasCenter = true;
            rp.centerX = c.x;
            rp.centerY = c.y;
            where.push_back(rp);
        }
    } else {
        where.push_back(params.footprint.roi);
    }
    std::vector<ShotRoi> out;
    for (const RoiParams& rp : where) {
        ShotRoi r;
        const RoiResult cut = extractRoi(frame, rp);
        if (!cut.ok) {
            r.error = cut.error;
        } else {
            r.roi = cut.roi;
            r.originX = cut.originX;
            r.originY = cut.originY;
            r.wholeImage = cut.wholeImage;
            r.warnings = cut.warnings;
        }
        out.push_back(std::move(r));
    }
    return out;
}

std::vector<FrameRoiResult> processShotRois(const std::vector<ShotRoi>& rois, const FootprintParams& params) {
    std::vector<FrameRoiResult> out;
    for (const ShotRoi& r : rois) {
        FrameRoiResult fr;
        if (!r.error.empty()) {
            fr.result.error = r.error;
        } else {
            fr.originX = r.originX;
            fr.originY = r.originY;
            fr.warnings = r.warnings;
            fr.result = processRoi(r.roi, params);
        }
        out.push_back(std::move(fr));
    }
    return out;
}

std::vector<FrameRoiResult> processFrame(const cv::Mat& image, const FootprintParams& params,
                                         const std::vector<cv::Point2d>& centres) {
    BatchParams bp;
    bp.footprint = params;
    bp.centres = centres;
    return processShotRois(cutShotRois(image, ShotSpec{}, bp), params);
}

ImageReadResult readShotFrame(const ShotSpec& shot, const BatchParams& params) { return readFrame(shot.file, params.read); }

bool loadShotRois(const ShotSpec& shot, const BatchParams& params, std::vector<ShotRoi>* rois, std::string* readError) {
    const ImageReadResult img = readShotFrame(shot, params);
    if (!img.ok) {
        *readError = img.error;
        return false;
    }
    *rois = cutShotRois(img.image, shot, params);
    return true;
}

}  // namespace lwb::core::footprint
