// A file written so that nothing is lost: through a temporary next to it,
// renamed over it only once every byte has been written and synced, so the
// old file stays whole until the new one is. Every write and the close are
// checked; the first failure is kept and said by error().
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace jl {

class OutputFile {
public:
    OutputFile() = default;
    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&& other) noexcept;
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    // A temporary neither committed nor kept is removed.
    ~OutputFile();

    // Creates the temporary "NAME.partial-XXXXXX" beside the file `path`
    // names (through symbolic links, which stay links). A name that is not
    // a regular file (a device such as /dev/null, a pipe, /dev/stdout)
    // cannot be replaced by a rename: it is opened and written directly.
    bool open(const std::string& path);
    // Buffered; false once anything has failed.
    bool write(std::string_view text);
    // Hands what is buffered to the system, so that a process killed later
    // leaves it in the temporary. What is buffered is one piece: when the
    // system takes only part of it (a full disk), the part is taken back.
    bool flush();
    // Flushes, syncs, closes, and renames the temporary over the file.
    bool commit();
    // Closes and renames the temporary to `other` instead, leaving the file
    // as it was: where an unfinished result goes. When `other` exists (the
    // scene, another output, an older result), it is left as it is and the
    // result stays in the temporary; kept() says where it is. A direct file
    // is only closed.
    bool keepAs(const std::string& other);
    const std::string& kept() const { return kept_; }

    bool direct() const { return direct_; }
    bool failed() const { return !error_.empty(); }
    const std::string& path() const { return path_; }
    const std::string& temporary() const { return temporary_; }
    // What failed, e.g. "cannot write the file: No space left on device".
    const std::string& error() const { return error_; }

private:
    bool fail(const std::string& what, int error);
    bool close();
    void discard();

    std::string path_;       // as given
    std::string target_;     // what the rename replaces: path_ with links resolved
    std::string temporary_;  // empty when direct or when renamed
    std::string kept_;       // where keepAs left the result
    std::string buffer_;
    std::size_t written_ = 0;  // bytes in the file, every flushed piece whole
    std::string error_;
    int fd_ = -1;
    bool direct_ = false;
};

// The whole file at once: `text` written to `path` through an OutputFile.
// Empty when it worked; else what failed ("cannot write the file: ...").
std::string writeWholeFile(const std::string& path, std::string_view text);

// True when OutputFile::open writes `path` directly rather than through a
// temporary: a device, a pipe, or one of the process's open descriptors.
bool writtenDirectly(const std::string& path);

}  // namespace jl
