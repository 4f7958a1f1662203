// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/html.hpp>

#include <preimage/error.hpp>
#include <preimage/render/svg.hpp>

#include <fstream>

namespace preimage::render {

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::close_list() {
  if (in_list_) body_ += "</ul>\n", in_list_ = false;
}

void HtmlReport::section(const std::string& heading) {
  close_list();
  body_ += "<h2>" + escape(heading) + "</h2>\n";
}

void HtmlReport::paragraph(const std::string& text) {
  close_list();
  body_ += "<p>" + escape(text) + "</p>\n";
}

void HtmlReport::result(const std::string& text) {
  if (!in_list_) body_ += "<ul>\n", in_list_ = true;
  body_ += "<li>" + escape(text) + "</li>\n";
}

void HtmlReport::figure(const std::string& svg, const std::string& caption) {
  close_list();
  body_ += "<figure>\n" + svg + "<figcaption>" + escape(caption) + "</figcaption>\n</figure>\n";
}

std::string HtmlReport::str() const {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title_) +
                    "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;padding:0 1em;color:#222}"
                    "figure{margin:1em 0}figcaption{color:#555;font-size:90%}h2{border-bottom:1px solid #ccc}</style>\n"
                    "</head>\n<body>\n<h1>" + escape(title_) + "</h1>\n" + body_;
  if (in_list_) out += "</ul>\n";
  out += "</body>\n</html>\n";
  return out;
}

void HtmlReport::save(const std::string& path) const {
  std::ofstream f(path);
  f << str();
  if (!f) throw InputError(path + ": cannot write file");
}

}  // namespace preimage::render
