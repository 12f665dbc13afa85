#pragma once
// A text input read line by line in blocks, so that a reader can hold one part of a file at a
// time: a regular file, a gzip-compressed one (several members one after the other, as
// readFileText), or "-" (the standard input, read once and kept by readFileText's rules).

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

namespace lwb::core {

class LineReader {
public:
    LineReader();
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;

    /// Opens `path` (the same checks as readFileText: a regular file, not a folder, FIFO or
    /// device). False with error() ("FILE: reason").
    bool open(const std::string& path);

    /// The next line without its line end: LF, CRLF, or CR alone in a file whose first block has
    /// no LF (an old Mac text; readFileText's plainText rule). A UTF-8 byte-order mark at the start
    /// is dropped. False at the end of the input, or on an error (error() not empty). The view
    /// holds until the next call. A line longer than maxLineBytes, or one holding a NUL byte, is
    /// an error naming its line.
    bool next(std::string_view* line);

    /// The number of the line `next` gave last (1-based).
    long lineNumber() const { return line_; }
    /// Where that line starts in the file (bytes), or -1 when the lines are not at offsets of
    /// the file: a gzip file, the standard input, a CR-only text.
    long long lineOffset() const { return gzip_ || stdin_ || crOnly_ ? -1 : lineOffset_; }
    /// The share of the input read so far, 0..1 (of the compressed bytes for a gzip file).
    double fraction() const;
    const std::string& error() const { return error_; }

    static constexpr size_t kBlock = 1 << 20;
    static constexpr size_t maxLineBytes = 16 << 20;

private:
    bool fill();         // more text into buf_ after pos_; false at the end or on error
    bool readRaw(char* to, size_t n, size_t* got);  // raw bytes of the file or the kept input
    bool noNul(std::string_view line);              // false (error_ set) when the line holds a NUL byte

    std::string path_, error_;
    std::ifstream file_;
    bool gzip_ = false, eofRaw_ = false, eofText_ = false, started_ = false, crOnly_ = false;
    long long rawSize_ = 0, rawRead_ = 0;
    struct Inflate;
    std::unique_ptr<Inflate> z_;
    std::string buf_;  // text not yet handed out starts at pos_
    size_t pos_ = 0;
    long line_ = 0;
    bool stdin_ = false;
    long long bufStart_ = 0;    // the file offset of buf_[0] (a plain file)
    long long lineOffset_ = -1;
};

}  // namespace lwb::core
