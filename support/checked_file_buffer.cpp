#include "support/checked_file_buffer.h"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace railjoint {

CheckedFileBuffer::CheckedFileBuffer(CheckedFileBuffer&& other) noexcept
    : std::streambuf(), fd_(other.fd_), error_(other.error_) {
  const std::ptrdiff_t pending = other.pptr() - other.pbase();
  buffer_ = std::move(other.buffer_);  // the same characters, the same address
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  pbump(static_cast<int>(pending));
  other.fd_ = -1;
  other.setp(nullptr, nullptr);
}

CheckedFileBuffer::~CheckedFileBuffer() {
  if (fd_ >= 0) ::close(fd_);  // not committed: what it held is discarded
}

bool CheckedFileBuffer::open(const std::filesystem::path& path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    error_ = errno;
    return false;
  }
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return true;
}

bool CheckedFileBuffer::close() {
  if (fd_ < 0) return error_ == 0;
  write_buffered();
  if (::close(fd_) != 0 && error_ == 0) error_ = errno;  // NFS and quotas report at close
  fd_ = -1;
  setp(nullptr, nullptr);
  return error_ == 0;
}

bool CheckedFileBuffer::write_all(const char* data, std::size_t count) {
  if (error_ != 0 || fd_ < 0) return false;
  while (count > 0) {
    const ssize_t n = ::write(fd_, data, count);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = n < 0 ? errno : EIO;
      return false;
    }
    data += n;
    count -= static_cast<std::size_t>(n);
  }
  return true;
}

bool CheckedFileBuffer::write_buffered() {
  const bool written = write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return written;
}

CheckedFileBuffer::int_type CheckedFileBuffer::overflow(int_type c) {
  if (fd_ < 0 || !write_buffered()) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int CheckedFileBuffer::sync() { return fd_ >= 0 && write_buffered() ? 0 : -1; }

std::streamsize CheckedFileBuffer::xsputn(const char* data, std::streamsize count) {
  if (fd_ < 0) return 0;
  // Large pieces (a staged file copied through rdbuf) skip the buffer.
  if (count >= static_cast<std::streamsize>(buffer_.size())) {
    if (!write_buffered() || !write_all(data, static_cast<std::size_t>(count))) return 0;
    return count;
  }
  return std::streambuf::xsputn(data, count);
}

}  // namespace railjoint
