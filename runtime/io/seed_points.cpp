#include "runtime/io/seed_points.h"

#include "runtime/io/quoted_text.h"
#include "runtime/io/read_input.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fgsg::rt::io {
namespace {

// At most this many seeds: each is a whole derivation's start.
constexpr size_t kMaxSeeds = 1'000'000;

// Three or six finite numbers separated by spaces, tabs, commas or one ':'.
bool parseSeed(std::string text, DeriveOptions::Seed& seed) {
  for (char& c : text)
    if (c == ',' || c == ':' || c == '\t') c = ' ';
  std::istringstream in(text);
  std::vector<double> v;
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const double d = std::strtod(word.c_str(), &end);
    if (*end != '\0' || !std::isfinite(d)) return false;
    v.push_back(d);
  }
  if (v.size() != 3 && v.size() != 6) return false;
  for (int k = 0; k < 3; ++k) seed.point[k] = v[k];
  seed.hasDirection = v.size() == 6;
  if (seed.hasDirection) {
    for (int k = 0; k < 3; ++k) seed.direction[k] = v[3 + k];
    if (std::hypot(v[3], v[4], v[5]) == 0) return false;
  }
  return true;
}

}  // namespace

bool readSeedPoints(const std::string& spec, std::vector<DeriveOptions::Seed>& seeds, std::string& error) {
  seeds.clear();
  const bool inlineList = spec.find(',') != std::string::npos;
  if (inlineList) {
    size_t from = 0;
    while (from <= spec.size()) {
      const size_t end = std::min(spec.find(';', from), spec.size());
      const std::string one = spec.substr(from, end - from);
      DeriveOptions::Seed seed;
      if (!parseSeed(one, seed)) {
        error = "--seed-points: '" + one + "' is not a seed: x,y,z or x,y,z:dx,dy,dz (a non-zero heading)";
        return false;
      }
      seeds.push_back(seed);
      from = end + 1;
    }
    return true;
  }
  std::string text;
  if (!readInputFile(spec, "a seed file", text, error)) return false;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r,") == std::string::npos) continue;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    DeriveOptions::Seed seed;
    if (!parseSeed(line, seed)) {
      error = spec + ":" + std::to_string(number) + ": expected a seed \"x y z\" or \"x y z dx dy dz\" (a non-zero heading), got " + quoteText(line);
      return false;
    }
    if (seeds.size() == kMaxSeeds) {
      error = spec + ":" + std::to_string(number) + ": more than 1000000 seeds";
      return false;
    }
    seeds.push_back(seed);
  }
  if (seeds.empty()) {
    error = spec + ": no seeds in this file (one \"x y z\" per line)";
    return false;
  }
  return true;
}

}  // namespace fgsg::rt::io
