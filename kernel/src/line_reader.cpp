#include "genmod/kernel/line_reader.hpp"

#include <cerrno>
#include <cstring>

namespace genmod {
namespace {
constexpr std::size_t kChunk = std::size_t{1} << 16;
}

LineReader::LineReader(std::istream& in, const TextReadLimits& limits)
    : stream_(&in), limits_(limits), buffer_(kChunk) {}

LineReader::LineReader(std::FILE* file, const TextReadLimits& limits)
    : file_(file), limits_(limits), buffer_(kChunk) {}

bool LineReader::refill() {
  std::size_t n = 0;
  if (stream_) {
    stream_->read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    n = static_cast<std::size_t>(stream_->gcount());
    if (stream_->bad()) throw TextReadError(line_number_ + 1, "read error");
  } else {
    n = std::fread(buffer_.data(), 1, buffer_.size(), file_);
    if (std::ferror(file_)) throw TextReadError(line_number_ + 1, std::string("read error: ") + std::strerror(errno));
  }
  pos_ = 0;
  end_ = n;
  return n > 0;
}

bool LineReader::next(std::string& line) {
  line.clear();
  bool any = false;  // a byte of this line (or its newline) was read
  for (;;) {
    if (pos_ == end_ && !refill()) {
      if (any) ++line_number_;
      return any;
    }
    const char* start = buffer_.data() + pos_;
    const std::size_t avail = end_ - pos_;
    const void* newline = std::memchr(start, '\n', avail);
    const std::size_t take = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - start) : avail;
    const std::size_t consumed = take + (newline ? 1 : 0);
    if (total_ + consumed > limits_.max_bytes)
      throw TextReadError(line_number_ + 1,
                          "the input is larger than the limit of " + std::to_string(limits_.max_bytes) + " bytes");
    if (line.size() + take > limits_.max_line)
      throw TextReadError(line_number_ + 1,
                          "a line is longer than the limit of " + std::to_string(limits_.max_line) + " bytes");
    total_ += consumed;
    line.append(start, take);
    pos_ += consumed;
    any = true;
    if (newline) {
      ++line_number_;
      return true;
    }
  }
}

}  // namespace genmod
