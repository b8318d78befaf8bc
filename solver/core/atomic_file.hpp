// Write-then-rename, so that a crash never leaves a half-written file under the real name.
#pragma once
#include <string>

namespace kolsky {

/// Temporary sibling name for `path` (same directory, so the rename is atomic).
std::string temporary_name(const std::string& path);
/// Renames tmp over final; throws std::runtime_error naming both on failure.
void commit_file(const std::string& tmp, const std::string& final_path);
/// Writes `content` to `path` through a temporary file.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace kolsky
