// Shared by the libFuzzer targets (fuzz/fuzz_*.cpp): the input bytes as text, and the one rule
// every target checks. A malformed input may only end in kolsky::InputError (the CLI's exit 2
// naming file, key or line, rule); any other exception escapes LLVMFuzzerTestOneInput and
// libFuzzer reports it as a crash, as it does for a sanitizer report, a leak or a hang.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/errors.hpp"

namespace kolsky::fuzz {

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs f; an InputError is the promised outcome for a bad input and is swallowed, after
/// checking that its message is one printable line (the CLI prints it with %s).
template <class F>
void expect_input_error_only(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    for (const char c : std::string_view(e.what()))
      if (static_cast<unsigned char>(c) < 0x20) __builtin_trap();
  }
}

}  // namespace kolsky::fuzz
