#include "core/common/line_reader.hpp"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>

#include "core/common/atomic_file.hpp"
#include "core/common/output_set.hpp"

namespace lwb::core {

struct LineReader::Inflate {
    z_stream zs{};
    bool live = false;
    std::string in;  // compressed bytes not yet inflated
    ~Inflate() {
        if (live) inflateEnd(&zs);
    }
};

LineReader::LineReader() = default;
LineReader::~LineReader() = default;

bool LineReader::open(const std::string& path) {
    path_ = path;
    if (isStandardStream(path)) {
        // The standard input cannot be read twice: readFileText keeps it (decompressed when gzip).
        stdin_ = true;
        if (!readFileText(path, &buf_, &error_)) return false;
        eofRaw_ = eofText_ = true;
        rawSize_ = rawRead_ = static_cast<long long>(buf_.size());
        return true;
    }
    if (regularFileProblem(path, &error_, &rawSize_)) return false;
    noteInputRead(path);
    file_.open(path, std::ios::binary);
    if (!file_) {
        error_ = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    char magic[2] = {0, 0};
    file_.read(magic, 2);
    const std::streamsize got = file_.gcount();
    file_.clear();
    file_.seekg(0);
    gzip_ = got == 2 && static_cast<unsigned char>(magic[0]) == 0x1f && static_cast<unsigned char>(magic[1]) == 0x8b;
    if (gzip_) {
        z_ = std::make_unique<Inflate>();
        if (inflateInit2(&z_->zs, 15 + 32) != Z_OK) {
            error_ = path + ": cannot start the gzip decoder";
            return false;
        }
        z_->live = true;
    }
    return true;
}

bool LineReader::readRaw(char* to, size_t n, size_t* got) {
    file_.read(to, static_cast<std::streamsize>(n));
    *got = static_cast<size_t>(file_.gcount());
    rawRead_ += static_cast<long long>(*got);
    if (*got < n) {
        if (file_.bad()) {
            error_ = path_ + ": read error after " + std::to_string(rawRead_) + " bytes: " + std::strerror(errno);
            return false;
        }
        eofRaw_ = true;
    }
    return true;
}

double LineReader::fraction() const {
    if (rawSize_ <= 0) return 1;
    return std::min(1.0, static_cast<double>(rawRead_) / static_cast<double>(rawSize_));
}

bool LineReader::fill() {
    if (eofText_) return false;
    // What is left moves to the front; then a block is appended.
    bufStart_ += static_cast<long long>(pos_);
    buf_.erase(0, pos_);
    pos_ = 0;
    const size_t old = buf_.size();
    try {
        if (!gzip_) {
            buf_.resize(old + kBlock);
            size_t got = 0;
            const bool ok = readRaw(buf_.data() + old, kBlock, &got);
            buf_.resize(old + got);
            if (!ok) return false;
            if (got == 0) eofText_ = true;
            return got > 0;
        }
        // gzip: inflate until a block of text is out or the stream ends.
        z_stream& zs = z_->zs;
        while (buf_.size() - old < kBlock) {
            if (zs.avail_in == 0 && !eofRaw_) {
                z_->in.resize(kBlock);
                size_t got = 0;
                if (!readRaw(z_->in.data(), kBlock, &got)) return false;
                z_->in.resize(got);
                zs.next_in = reinterpret_cast<Bytef*>(z_->in.data());
                zs.avail_in = static_cast<uInt>(got);
            }
            char out[1 << 16];
            zs.next_out = reinterpret_cast<Bytef*>(out);
            zs.avail_out = sizeof out;
            const int rc = inflate(&zs, Z_NO_FLUSH);
            buf_.append(out, sizeof out - zs.avail_out);
            if (rc == Z_STREAM_END) {
                // Another member may follow (cat a.gz b.gz > c.gz); anything else is an error.
                if (zs.avail_in == 0 && !eofRaw_) {
                    z_->in.resize(2);
                    size_t got = 0;
                    if (!readRaw(z_->in.data(), 2, &got)) return false;
                    z_->in.resize(got);
                    zs.next_in = reinterpret_cast<Bytef*>(z_->in.data());
                    zs.avail_in = static_cast<uInt>(got);
                }
                if (zs.avail_in == 0) {
                    eofText_ = true;
                    break;
                }
                if (zs.avail_in >= 2 && zs.next_in[0] == 0x1f && zs.next_in[1] == 0x8b) {
                    inflateReset(&zs);
                    continue;
                }
                error_ = path_ + ": data after the end of the gzip stream";
                return false;
            }
            if (rc == Z_BUF_ERROR && zs.avail_in == 0 && eofRaw_) {
                error_ = path_ + ": the gzip stream is truncated (it ends before its end marker)";
                return false;
            }
            if (rc != Z_OK && rc != Z_BUF_ERROR) {
                error_ = path_ + ": not a valid gzip stream: " + (zs.msg ? zs.msg : "data error");
                return false;
            }
        }
        return buf_.size() > old || !eofText_;
    } catch (const std::bad_alloc&) {
        error_ = path_ + ": out of memory reading line " + std::to_string(line_ + 1);
        return false;
    }
}

// A NUL byte in a line: readFileText's refusal, with the same message (the streamed and the
// whole read of a file say the same).
bool LineReader::noNul(std::string_view line) {
    if (!std::memchr(line.data(), 0, line.size())) return true;
    error_ = nulByteMessage(path_, line_);
    return false;
}

bool LineReader::next(std::string_view* line) {
    if (!error_.empty()) return false;
    if (!started_) {
        started_ = true;
        while (buf_.size() < 3 && !eofText_)
            if (!fill() && !error_.empty()) return false;
        if (buf_.size() >= 3 && static_cast<unsigned char>(buf_[0]) == 0xEF &&
            static_cast<unsigned char>(buf_[1]) == 0xBB && static_cast<unsigned char>(buf_[2]) == 0xBF)
            pos_ = 3;
        if (!eofText_) fill();
        if (!error_.empty()) return false;
        const std::string_view head = std::string_view(buf_).substr(pos_);
        crOnly_ = head.find('\n') == std::string_view::npos && head.find('\r') != std::string_view::npos;
    }
    const char eol = crOnly_ ? '\r' : '\n';
    for (;;) {
        const size_t end = buf_.find(eol, pos_);
        if (end != std::string::npos) {
            lineOffset_ = bufStart_ + static_cast<long long>(pos_);
            *line = std::string_view(buf_).substr(pos_, end - pos_);
            pos_ = end + 1;
            ++line_;
            return noNul(*line);
        }
        if (buf_.size() - pos_ > maxLineBytes) {
            error_ = path_ + ":" + std::to_string(line_ + 1) + ": a line longer than " + std::to_string(maxLineBytes >> 20) +
                     " MiB: not a text file of records";
            return false;
        }
        if (eofText_ || !fill()) {
            if (!error_.empty()) return false;
            if (pos_ >= buf_.size()) return false;
            lineOffset_ = bufStart_ + static_cast<long long>(pos_);
            *line = std::string_view(buf_).substr(pos_);  // the last line, without a line end
            pos_ = buf_.size();
            ++line_;
            return noNul(*line);
        }
    }
}

}  // namespace lwb::core
