// The JUnit XML file of a run: one testcase per property, failed with its
// shrunk reproducer, so that CI systems show each property on its own.
#pragma once

#include <deque>
#include <fstream>
#include <string>

#include "checker.hpp"

namespace check {

inline std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 has no other control characters than these three
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t' || c == '\r') out += c;
    }
  }
  return out;
}

// The domain and the per-family table go to the suite's properties and
// system-out; where a property breaks goes to its failure's text.
inline bool write_junit(const std::string& path, const std::string& candidate, const std::string& domain,
                        const std::string& table, const std::deque<record>& records) {
  std::ofstream xml(path);
  if (!xml) return false;
  long failures = 0;
  double seconds = 0;
  for (const auto& r : records) {
    failures += r.failed ? 1 : 0;
    seconds += r.seconds;
  }
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites>\n<testsuite name=\"contact-check\" tests=\"" << records.size() << "\" failures=\"" << failures
      << "\" errors=\"0\" time=\"" << seconds << "\">\n"
      << "  <properties><property name=\"candidate\" value=\"" << xml_escaped(candidate)
      << "\"/><property name=\"domain\" value=\"" << xml_escaped(domain) << "\"/></properties>\n";
  for (const auto& r : records) {
    xml << "  <testcase classname=\"contact-check\" name=\"" << xml_escaped(r.name) << "\" time=\"" << r.seconds << "\"";
    if (!r.failed) {
      xml << "/>\n";
      continue;
    }
    std::string body;
    for (const auto& [which, f] : r.first) {
      body += f.reason + "\n";
      for (const auto& line : f.lines) body += "  " + line + "\n";
    }
    for (const auto& line : r.where) body += "where: " + line + "\n";
    const std::string message =
        r.claim + ": fails on " + std::to_string(r.failed) + " of " + std::to_string(r.tried) + " trials";
    xml << ">\n    <failure message=\"" << xml_escaped(message) << "\">" << xml_escaped(body) << "</failure>\n"
        << "  </testcase>\n";
  }
  xml << "  <system-out>per family and case:\n" << xml_escaped(table) << "</system-out>\n"
      << "</testsuite>\n</testsuites>\n";
  return static_cast<bool>(xml);
}

}  // namespace check
