#include "core/common/image_codecs.hpp"

#include <dlfcn.h>
#include <mutex>
#include <unistd.h>

#include "core/common/codec_api.hpp"
#include "core/common/install_paths.hpp"
#include "core/common/output_set.hpp"

#ifndef LWB_CODECS_BUILD_PATH
#define LWB_CODECS_BUILD_PATH ""
#endif

namespace lwb::core {
namespace codecs {
namespace {
struct Loaded {
    const CodecModule* module = nullptr;
    std::string why;
};

Loaded load() {
    Loaded l;
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("LWB_CODECS"); env && *env) candidates.emplace_back(env);
    for (const std::string& c : helperCandidates("liblaserwb_codecs.so")) candidates.push_back(c);
    if (*LWB_CODECS_BUILD_PATH) candidates.emplace_back(LWB_CODECS_BUILD_PATH);
    for (const std::string& path : candidates) {
        if (access(path.c_str(), R_OK) != 0) {
            l.why += (l.why.empty() ? "" : "; ") + path + ": not found";
            continue;
        }
        void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            const char* e = dlerror();
            l.why += (l.why.empty() ? "" : "; ") + std::string(e ? e : path + ": cannot be loaded");
            continue;
        }
        using Entry = const CodecModule* (*)();
        const auto entry = reinterpret_cast<Entry>(dlsym(h, "lwb_codec_module"));
        const CodecModule* m = entry ? entry() : nullptr;
        if (!m || m->abi != kCodecAbi || m->size != sizeof(CodecModule)) {
            l.why += (l.why.empty() ? "" : "; ") + path + ": not the codec module of this build";
            continue;  // (left loaded: unloading a library that may have run constructors is not worth the risk)
        }
        l.module = m;
        l.why.clear();
        return l;
    }
    l.why = "the image codec module (liblaserwb_codecs.so) cannot be loaded: " + l.why;
    return l;
}
}  // namespace

const CodecModule* codecModule(std::string* why) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.module && why) *why = loaded.why;
    return loaded.module;
}

namespace {
const CodecModule& required() {
    std::string why;
    const CodecModule* m = codecModule(&why);
    if (!m) throw cv::Exception(cv::Error::StsError, why, "image codecs", __FILE__, __LINE__);
    return *m;
}
}  // namespace
}  // namespace codecs

cv::Mat imageDecode(const cv::Mat& buf, int flags) { return codecs::required().decode(buf, flags); }

bool imageEncode(const std::string& ext, const cv::Mat& image, std::vector<uchar>& buf, const std::vector<int>& params) {
    return codecs::required().encode(ext, image, &buf, params);
}

cv::Mat imageRead(const std::string& path, int flags) {
    noteInputRead(path);
    return codecs::required().read(path, flags);
}

}  // namespace lwb::core
