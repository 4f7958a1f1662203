// SPDX-License-Identifier: Apache-2.0
// A self-contained HTML report: sections of text and inline SVG figures.
#pragma once
#include <string>
#include <vector>

namespace preimage::render {

class HtmlReport {
 public:
  explicit HtmlReport(std::string title);
  void section(const std::string& heading);
  void paragraph(const std::string& text);          // plain text, escaped
  void result(const std::string& text);             // a one-line result, shown as a list item
  void figure(const std::string& svg, const std::string& caption);
  std::string str() const;
  void save(const std::string& path) const;

 private:
  std::string title_;
  std::string body_;
  bool in_list_ = false;
  void close_list();
};

}  // namespace preimage::render
