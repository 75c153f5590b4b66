#pragma once
// The stream buffer behind AtomicFile: a file written through write(2) that
// keeps the errno of the first write (or close) that failed. std::filebuf
// reports only that something failed, and errno read afterwards is whatever
// a later call left there ("No such file or directory" for a "File too
// large"), so the message would name the wrong cause.

#include <filesystem>
#include <streambuf>
#include <vector>

namespace railjoint {

class CheckedFileBuffer : public std::streambuf {
 public:
  CheckedFileBuffer() = default;
  CheckedFileBuffer(CheckedFileBuffer&& other) noexcept;
  CheckedFileBuffer& operator=(CheckedFileBuffer&&) = delete;
  ~CheckedFileBuffer() override;

  /// Creates or truncates `path` for writing (0666 less the umask). False
  /// with error() set when it cannot.
  bool open(const std::filesystem::path& path);
  /// Writes what is buffered and closes the file. False when this or any
  /// earlier write failed; error() says why.
  bool close();
  /// errno of the first failure, 0 when none.
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;
  std::streamsize xsputn(const char* data, std::streamsize count) override;

 private:
  bool write_buffered();
  bool write_all(const char* data, std::size_t count);

  int fd_ = -1;
  int error_ = 0;
  std::vector<char> buffer_ = std::vector<char>(64 * 1024);
};

}  // namespace railjoint
