#include "core/footprint/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sys/stat.h>

#include "core/common/atomic_file.hpp"
#include "core/common/image_codecs.hpp"
#include "core/common/image_header.hpp"
#include "core/common/text.hpp"

namespace lwb::core::footprint {

namespace {
std::string extensionOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return toLower(path.substr(dot + 1));
}

bool isRaw(const std::string& ext) { return ext == "raw" || ext == "bin"; }

ImageReadResult fail(const std::string& path, const std::string& what) {
    ImageReadResult r;
    r.error = path + ": " + what;
    return r;
}

ImageReadResult readRaw(const std::string& path, const ImageReadParams& p) {
    if (p.rawWidth <= 0 || p.rawHeight <= 0)
        return fail(path, "raw 16-bit frame needs its size (--raw-size WxH)");
    if (p.rawWidth > 65536 || p.rawHeight > 65536)
        return fail(path, "raw size " + std::to_string(p.rawWidth) + "x" + std::to_string(p.rawHeight) +
                              " is implausibly large");
    if (p.maxPixels > 0 && static_cast<long long>(p.rawWidth) * p.rawHeight > p.maxPixels)
        return fail(path, "raw size " + std::to_string(p.rawWidth) + "x" + std::to_string(p.rawHeight) + " = " +
                              std::to_string(static_cast<long long>(p.rawWidth) * p.rawHeight) +
                              " pixels is more than the limit of " + std::to_string(p.maxPixels) +
                              " pixels (raise it with --max-pixels)");
    std::string bytes, err;
    if (!readFileBytes(path, &bytes, &err)) return fail(path, err.substr(err.find(": ") + 2));
    const size_t want = size_t(p.rawWidth) * size_t(p.rawHeight) * 2;
    if (bytes.size() != want)
        return fail(path, "raw file holds " + std::to_string(bytes.size()) + " bytes, but " +
                              std::to_string(p.rawWidth) + "x" + std::to_string(p.rawHeight) +
                              " 16-bit pixels need " + std::to_string(want));
    cv::Mat img(p.rawHeight, p.rawWidth, CV_16UC1);
    const auto* src = reinterpret_cast<const unsigned char*>(bytes.data());
    auto* dst = img.ptr<uint16_t>();
    for (size_t i = 0; i < size_t(p.rawWidth) * p.rawHeight; ++i) {
        const unsigned lo = src[2 * i], hi = src[2 * i + 1];
        dst[i] = static_cast<uint16_t>(p.rawBigEndian ? (lo << 8 | hi) : (hi << 8 | lo));
    }
    ImageReadResult r;
    r.storedBits = 16;
    img.convertTo(r.image, CV_32F);
    r.ok = true;
    return r;
}
}  // namespace

bool isFrameFile(const std::string& path) {
    const std::string e = extensionOf(path);
    return e == "png" || e == "tif" || e == "tiff" || e == "pgm" || isRaw(e);
}

ImageReadResult readFrame(const std::string& path, const ImageReadParams& params) {
    std::string err;
    long long size = 0;
    struct stat st {};
    if (!isStandardStream(path)) {  // ("-": one frame on standard input, told by its content)
        if (::stat(path.c_str(), &st) != 0) return fail(path, "no such file");
        if (regularFileProblem(path, &err, &size)) return fail(path, err.substr(std::min(err.size(), path.size() + 2)));
        if (size == 0) return fail(path, "empty file");
    }
    const std::string ext = extensionOf(path);
    // A file larger than any frame within the pixel limit could be (8 bytes a pixel, twice the
    // widest sample, and a megabyte of header) is refused from its size, before it is read (a
    // 2 GiB sparse file was read whole first); a raw frame must be exactly its pixels.
    if (!isStandardStream(path) && params.maxPixels > 0 && size > params.maxPixels * 8 + (1LL << 20))
        return fail(path, std::to_string(size) + " bytes: larger than a frame of at most " + std::to_string(params.maxPixels) +
                              " pixels can be (raise the limit with --max-pixels)");
    if (!isStandardStream(path) && isRaw(ext) && params.rawWidth > 0 && params.rawHeight > 0 &&
        size != static_cast<long long>(params.rawWidth) * params.rawHeight * 2 && params.rawWidth <= 65536 &&
        params.rawHeight <= 65536)
        return fail(path, "raw file holds " + std::to_string(size) + " bytes, but " + std::to_string(params.rawWidth) + "x" +
                              std::to_string(params.rawHeight) + " 16-bit pixels need " +
                              std::to_string(static_cast<long long>(params.rawWidth) * params.rawHeight * 2));
    ImageReadResult r;
    if (isRaw(ext)) {
        r = readRaw(path, params);
        if (!r.ok) return r;
    } else {
        cv::Mat m;
        try {
            std::string bytes;
            if (!readFileBytes(path, &bytes, &err)) return fail(path, err.substr(std::min(err.size(), path.size() + 2)));
            if (const std::string why = imageSizeProblem(bytes, path, params.maxPixels); !why.empty()) {
                r.error = why;
                return r;
            }
            const cv::Mat buf(1, static_cast<int>(std::min<size_t>(bytes.size(), INT32_MAX)), CV_8U, bytes.data());
            m = imageDecode(buf, cv::IMREAD_UNCHANGED);
        } catch (const cv::Exception& e) {
            return fail(path, std::string("cannot decode image: ") + e.what());
        } catch (const std::bad_alloc&) {
            return fail(path, "out of memory decoding the image");
        }
        if (m.empty()) return fail(path, "not a readable image (unknown format, truncated or corrupt)");
        if (m.channels() != 1)
            return fail(path, std::to_string(m.channels()) +
                                  "-channel (colour) image; footprint frames are single-channel 16-bit");
        switch (m.depth()) {
            case CV_16U: r.storedBits = 16; break;
            case CV_32F: r.storedBits = 32; break;
            case CV_8U:
            case CV_8S:
                return fail(path, "8-bit image; footprint frames must be 16-bit (14-bit data stored in 16 bits)");
            default:
                return fail(path, "unsupported pixel type (need unsigned 16-bit or 32-bit float)");
        }
        m.convertTo(r.image, CV_32F);
    }
    if (r.image.cols < 3 || r.image.rows < 3)
        return fail(path, "image is only " + std::to_string(r.image.cols) + "x" + std::to_string(r.image.rows) + " px");
    if (!cv::checkRange(r.image, true))
        return fail(path, "image holds NaN or infinite pixel values");
    double mn = 0, mx = 0;
    cv::minMaxLoc(r.image, &mn, &mx);
    if (mn < 0) return fail(path, "image holds negative pixel values");
    if (mx <= 0) return fail(path, "image is all zero (blank frame)");
    r.maxValue = mx;
    r.ok = true;
    return r;
}

bool expandInputs(const std::vector<std::string>& inputs, std::vector<std::string>* files,
                  std::string* error, bool keepMissing) {
    for (const auto& in : inputs) {
        if (isStandardStream(in)) {  // one frame on standard input
            if (std::count(files->begin(), files->end(), in)) {
                *error = "-: standard input given twice";
                return false;
            }
            files->push_back(in);
            continue;
        }
        struct stat st {};
        if (::stat(in.c_str(), &st) != 0) {
            if (keepMissing && isFrameFile(in)) {
                files->push_back(in);
                continue;
            }
            *error = in + ": no such file or folder";
            return false;
        }
        if (!S_ISDIR(st.st_mode)) {
            files->push_back(in);
            continue;
        }
        DIR* d = ::opendir(in.c_str());
        if (!d) {
            *error = in + ": cannot open folder: " + std::strerror(errno);
            return false;
        }
        std::vector<std::string> found;
        while (dirent* e = ::readdir(d)) {
            const std::string name = e->d_name;
            if (name.empty() || name[0] == '.') continue;
            const std::string full = (in.back() == '/' ? in : in + "/") + name;
            struct stat fs {};
            if (::stat(full.c_str(), &fs) == 0 && S_ISREG(fs.st_mode) && isFrameFile(name))
                found.push_back(full);
        }
        ::closedir(d);
        std::sort(found.begin(), found.end());
        files->insert(files->end(), found.begin(), found.end());
    }
    return true;
}

bool writeFrame16(const std::string& path, const cv::Mat& image16, std::string* error) {
    if (image16.type() != CV_16UC1) {
        *error = path + ": writeFrame16 needs a 16-bit single-channel image";
        return false;
    }
    const std::string ext = extensionOf(path);
    std::string bytes;
    if (isRaw(ext)) {
        bytes.resize(image16.total() * 2);
        size_t k = 0;
        for (int r = 0; r < image16.rows; ++r)
            for (int c = 0; c < image16.cols; ++c) {
                const uint16_t v = image16.at<uint16_t>(r, c);
                bytes[k++] = static_cast<char>(v & 0xFF);
                bytes[k++] = static_cast<char>(v >> 8);
            }
    } else {
        std::vector<uchar> buf;
        try {
            if (!imageEncode("." + ext, image16, buf)) {
                *error = path + ": cannot encode as ." + ext;
                return false;
            }
        } catch (const cv::Exception& e) {
            *error = path + ": cannot encode: " + e.what();
            return false;
        }
        bytes.assign(buf.begin(), buf.end());
    }
    return writeFileAtomic(path, bytes, error);
}

}  // namespace lwb::core::footprint
