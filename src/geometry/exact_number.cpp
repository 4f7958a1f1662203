// SPDX-License-Identifier: Apache-2.0
// Exact numbers as text: rational strings out, rational and decimal strings in.
#include <preimage/geometry/kernel.hpp>

#include <cstdlib>
#include <sstream>

namespace preimage::geometry {

std::string exact_string(const ExactFT& v) {
  std::ostringstream ss;
  ss << CGAL::exact(v);
  return ss.str();
}

namespace {

using ET = ExactFT::ET;

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// The exact integer of a string of decimal digits. Leading zeros are dropped: some exact
// types read a leading 0 as octal.
ET integer(std::string_view digits) {
  const auto first = digits.find_first_not_of('0');
  return first == std::string_view::npos ? ET(0) : ET(std::string(digits.substr(first)));
}

ET power_of_ten(std::size_t k) {
  ET r(1), b(10);
  for (; k > 0; k >>= 1, b *= b)
    if (k & 1) r *= b;
  return r;
}

}  // namespace

std::optional<ExactFT> parse_exact_number(std::string_view text) {
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) negative = text[0] == '-', text.remove_prefix(1);
  ET value;
  if (const auto slash = text.find('/'); slash != std::string_view::npos) {
    const std::string_view p = text.substr(0, slash), q = text.substr(slash + 1);
    if (!all_digits(p) || !all_digits(q)) return std::nullopt;
    const ET den = integer(q);
    if (CGAL::is_zero(den)) return std::nullopt;
    value = integer(p) / den;
  } else {
    // Decimal: digits, optionally '.' and digits (at least one digit in all), optionally an
    // exponent.
    long exponent = 0;
    if (const auto e = text.find_first_of("eE"); e != std::string_view::npos) {
      std::string_view x = text.substr(e + 1);
      text = text.substr(0, e);
      bool neg_exp = false;
      if (!x.empty() && (x[0] == '-' || x[0] == '+')) neg_exp = x[0] == '-', x.remove_prefix(1);
      if (!all_digits(x) || x.size() > 3) return std::nullopt;
      exponent = std::strtol(std::string(x).c_str(), nullptr, 10);
      if (exponent > 400) return std::nullopt;
      if (neg_exp) exponent = -exponent;
    }
    std::string_view whole = text, fraction;
    if (const auto dot = text.find('.'); dot != std::string_view::npos) whole = text.substr(0, dot), fraction = text.substr(dot + 1);
    if (whole.empty() && fraction.empty()) return std::nullopt;
    if ((!whole.empty() && !all_digits(whole)) || (!fraction.empty() && !all_digits(fraction))) return std::nullopt;
    value = integer(std::string(whole) + std::string(fraction));
    exponent -= static_cast<long>(fraction.size());
    if (exponent > 0) value *= power_of_ten(static_cast<std::size_t>(exponent));
    if (exponent < 0) value /= power_of_ten(static_cast<std::size_t>(-exponent));
  }
  if (negative) value = -value;
  return ExactFT(value);
}

}  // namespace preimage::geometry
