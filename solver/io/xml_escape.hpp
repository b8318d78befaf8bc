// Text for XML and HTML (the XDMF snapshot index, the reports index): the five characters that
// would end an attribute or open a tag, escaped. One copy for both writers.
#pragma once
#include <string>

namespace kolsky::io {

/// s with & < > " as entities; everything else (UTF-8 included) unchanged.
inline std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace kolsky::io
