#include "io/atomic_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <mutex>
#include <stdexcept>

namespace sph {

namespace {
std::mutex failures_mutex;
std::vector<std::string>& failures() {
  static std::vector<std::string> f;
  return f;
}
}  // namespace

std::filesystem::path partial_path(const std::filesystem::path& final_path) {
  return std::filesystem::path(final_path.string() + ".part");
}

std::string write_error(const std::string& what, const std::filesystem::path& file) {
  const int e = errno;  // first: the calls below may set it
  return what + " " + file.string() + ": " + (e ? std::strerror(e) : "stream error") + " (errno " + std::to_string(e) + ")";
}

void commit_partial(const std::filesystem::path& partial, const std::filesystem::path& final_path) {
  if (std::rename(partial.c_str(), final_path.c_str()) != 0)
    throw std::runtime_error(write_error("cannot rename " + partial.string() + " to", final_path));
}

void close_or_discard(int uncaught_at_open, const std::function<void()>& close,
                      const std::function<void()>& discard) noexcept {
  try {
    if (std::uncaught_exceptions() > uncaught_at_open) discard();
    else close();
  } catch (const std::exception& e) {
    record_output_failure(e.what());
    std::cerr << "error: " << e.what() << "\n";
  }
}

void record_output_failure(const std::string& message) {
  std::lock_guard<std::mutex> lock(failures_mutex);
  failures().push_back(message);
}

std::vector<std::string> output_failures() {
  std::lock_guard<std::mutex> lock(failures_mutex);
  return failures();
}

void throw_if_output_failed() {
  const auto f = output_failures();
  if (f.empty()) return;
  std::string message = f.front();
  if (f.size() > 1) message += " (and " + std::to_string(f.size() - 1) + " more output failures)";
  throw std::runtime_error(message + "; no completion record written");
}

}  // namespace sph
