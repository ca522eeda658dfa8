// Outputs that appear whole or not at all (issue 47): a file is written under a temporary name beside its final
// one (<name>.part, in the same folder, so the rename is atomic) and renamed when complete. A run killed at any
// instant (SIGKILL, a power cut before the page cache is written aside) leaves the previous complete file or
// none, never half of one; a leftover .part is overwritten by the next run and read by nothing.
//
// A write that fails (a full disk, ENOSPC; a file-size limit, EFBIG: the driver frame ignores SIGXFSZ so that
// the limit arrives as an error and not as a kill) throws std::runtime_error naming the file and errno. Where
// it cannot throw (in a destructor), the failure is recorded here instead, and the driver frame refuses to
// write the run's completion record while any is recorded, so the next make reruns that run.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sph {

/// The temporary name a file is written under until it is complete.
std::filesystem::path partial_path(const std::filesystem::path& final_path);

/// Renames `partial` to `final_path` (atomic within one file system); throws naming both and errno on failure.
void commit_partial(const std::filesystem::path& partial, const std::filesystem::path& final_path);

/// "<what> <file>: <strerror(errno)> (errno N)": the message of a failed write, read right after the failing call.
std::string write_error(const std::string& what, const std::filesystem::path& file);

/// What a writer's destructor does: while an exception unwinds past it (more uncaught exceptions than when it
/// was opened: the run failed while the file was being written), discard(); else close(), a failure of which is
/// recorded (record_output_failure) and printed, as a destructor cannot throw it.
void close_or_discard(int uncaught_at_open, const std::function<void()>& close,
                      const std::function<void()>& discard) noexcept;

/// Failures recorded where no exception could be thrown (a writer closed by its destructor); thread-safe.
void record_output_failure(const std::string& message);
std::vector<std::string> output_failures();
/// Throws std::runtime_error with the recorded failures, if any: before a run's completion record is written.
void throw_if_output_failed();

}  // namespace sph
