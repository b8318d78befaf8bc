// Where this binary came from: commit, build type, version. Defined in one generated source
// (solver/core/build_info.cpp.in, configured into the build folder), so that a new commit
// recompiles that one file instead of every file of the project (a compile definition on the
// library would change every object's flags).
#pragma once

namespace kolsky::build_info {

const char* git_commit();  ///< short SHA of HEAD at configure time, or "unknown"
const char* build_type();  ///< CMAKE_BUILD_TYPE
const char* version();     ///< PROJECT_VERSION

}  // namespace kolsky::build_info
