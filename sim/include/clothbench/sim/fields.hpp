#pragma once
/// Field tables: every scene key of a parameter struct written once, as one row
///   v(Key{name, unit, doc}, member, Rule)
/// in a function `visit_fields(params, v)`. The scene reader (bench/src/scene.cpp), the
/// configuration hash, the validation of the structs (check_fields, below) and the test that
/// scenes/README.md documents every key are visitors of the same rows; adding a key is one row.
/// The rows' order is the configuration hash's order.
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "clothbench/sim/types.hpp"

namespace clothbench::fields {

/// Whether the configuration hash includes the row.
enum class Hash {
  kAlways,
  kWhenNonzero,  ///< only when set: a key added after hashes were published leaves their default hashes as they were
  kUnlessOne,    ///< as kWhenNonzero for a factor, whose unset value is 1 (every component of a triple)
  kNever,        ///< a label or preset whose effects the other rows carry
};

/// A row's key: the TOML key, its unit ("" when none) and one line of documentation.
struct Key {
  const char* name;
  const char* unit;
  const char* doc;
  Hash hash = Hash::kAlways;
};

/// A number (or integer, for integral members) in the closed interval [lo, hi].
struct Range {
  double lo, hi;
};
/// As Range, or the word "auto", kept as 0.
struct RangeOrAuto {
  double lo, hi;
};
/// A number given in the key's unit in [lo, hi], kept as value x to_member (its key value is member x to_key).
struct Scaled {
  double lo, hi, to_member, to_key;
};
/// An integer of a short list; `says` lists them for messages.
struct OneOf {
  std::vector<int> values;
  const char* says;
};
/// true or false.
struct Flag {};
/// Any string.
struct Text {};
/// Three finite numbers [x, y, z].
struct Triple {};
/// A name: `parse` (throws std::invalid_argument naming the choices) gives the member, `print` its name.
template <class Parse, class Print>
struct Choice {
  Parse parse;
  Print print;
};
template <class Parse, class Print>
Choice<Parse, Print> choice(Parse parse, Print print) {
  return {parse, print};
}
/// A name kept as the string itself, accepted by `check` (which throws std::invalid_argument otherwise).
template <class Check>
auto checked(Check check) {
  return choice(
      [check](const std::string& v) {
        check(v);
        return v;
      },
      [](const std::string& v) { return v; });
}

/// A rule's bounds as text: "[lo, hi]".
inline std::string bounds(double lo, double hi) {
  const auto text = [](double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  return "[" + text(lo) + ", " + text(hi) + "]";
}

/// The validation visitor: throws std::invalid_argument naming the first member out of its row's bounds.
struct Checker {
  template <class T>
  void operator()(const Key& k, const T& m, const Range& r) const {
    in(k, double(m), r.lo, r.hi);
  }
  template <class T>
  void operator()(const Key& k, const T& m, const RangeOrAuto& r) const {
    if (double(m) != 0) in(k, double(m), r.lo, r.hi);
  }
  template <class T>
  void operator()(const Key& k, const T& m, const Scaled& r) const {
    in(k, double(m) * r.to_key, r.lo, r.hi);
  }
  void operator()(const Key& k, int m, const OneOf& r) const {
    for (const int v : r.values)
      if (m == v) return;
    fail(k, double(m), r.says);
  }
  void operator()(const Key&, bool, Flag) const {}
  void operator()(const Key&, const std::string&, Text) const {}
  void operator()(const Key& k, const Vec3& m, Triple) const {
    if (!m.allFinite()) fail(k, double(m.norm()), "three finite numbers");
  }
  template <class T, class P, class Q>
  void operator()(const Key&, const T& m, const Choice<P, Q>& c) const {
    c.parse(c.print(m));  // a string member must name a known choice
  }

 private:
  static void in(const Key& k, double v, double lo, double hi) {
    if (!std::isfinite(v) || v < lo || v > hi) fail(k, v, "in " + bounds(lo, hi));
  }
  [[noreturn]] static void fail(const Key& k, double v, const std::string& rule) {
    const std::string unit = *k.unit ? std::string(" ") + k.unit : "";
    throw std::invalid_argument(std::string(k.name) + " = " + std::to_string(v) + ": must be " + rule + unit);
  }
};

/// Throws std::invalid_argument naming the first field of `params` outside its row's bounds.
template <class P>
void check_fields(const P& params) {
  Checker checker;
  visit_fields(params, checker);
}

}  // namespace clothbench::fields
