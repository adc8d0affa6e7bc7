#include "cli/command_line.h"
#include "frontend/did_you_mean.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace fgsg::cli {

CommandLine::CommandLine(std::string command) : command_(std::move(command)), app_(std::make_unique<CLI::App>()) {
  app_->set_help_flag();  // main.cpp answers --help with fgsg's own usage text
  app_->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

CommandLine::~CommandLine() = default;

std::string CommandLine::longName(const std::string& names) {
  size_t from = 0;
  std::string first;
  while (from <= names.size()) {
    size_t comma = names.find(',', from);
    if (comma == std::string::npos) comma = names.size();
    const std::string name = names.substr(from, comma - from);
    if (first.empty()) first = name;
    if (name.rfind("--", 0) == 0) return name;
    from = comma + 1;
  }
  return first;
}

void CommandLine::input(std::string& file, std::string what) {
  input_ = &file;
  inputWhat_ = std::move(what);
  app_->add_option("input", inputs_);
}

void CommandLine::flag(const std::string& names, bool& target) { app_->add_flag(names, target); }

void CommandLine::text(const std::string& names, std::string& target) { app_->add_option(names, target); }

void CommandLine::number(const std::string& names, double& target) {
  option(names, [&target, flag = longName(names)](const std::string& v) { target = parseNumber(flag, v); });
}

void CommandLine::point(const std::string& names, double (&target)[3]) {
  option(names, [&target, flag = longName(names)](const std::string& v) { parsePoint(flag, v, target); });
}

void CommandLine::option(const std::string& names, std::function<void(const std::string&)> use) {
  app_->add_option_function<std::string>(names, std::move(use));
}

void CommandLine::repeated(const std::string& names, std::function<void(const std::string&)> use) {
  app_->add_option_function<std::vector<std::string>>(names,
                                                      [use = std::move(use)](const std::vector<std::string>& all) {
                                                        for (const std::string& v : all) use(v);
                                                      })
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->expected(1);
}

void CommandLine::values(const std::string& names, int minCount, int maxCount,
                         std::function<void(const std::vector<std::string>&)> use) {
  app_->add_option_function<std::vector<std::string>>(names, std::move(use))->expected(minCount, maxCount);
}

void CommandLine::parse(const Args& args) {
  const std::string seeHelp = " (see fgsg " + command_ + " --help)";
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 pops from the back
  try {
    app_->parse(reversed);
  } catch (const CLI::ExtrasError&) {
    const std::vector<std::string> extra = app_->remaining();
    const std::string first = extra.empty() ? std::string() : extra.front();
    if (!first.empty() && first[0] == '-') {
      std::vector<std::string> names;  // every spelling this command accepts
      for (const CLI::Option* o : app_->get_options()) {
        for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
        for (const std::string& n : o->get_snames()) names.push_back("-" + n);
      }
      const std::string meant = frontend::closestName(first.substr(0, first.find('=')), names);
      throw UsageError{"unknown option '" + first + "'" + (meant.empty() ? "" : "; did you mean " + meant + "?") +
                       seeHelp};
    }
    throw UsageError{"unexpected argument '" + first + "'" + seeHelp};
  } catch (const CLI::ArgumentMismatch& e) {
    // An option with too few values: it was the last argument, or values ran out. CLI11
    // says "--output: 1 required TEXT missing" for a lone missing value.
    const std::string what = e.what();
    const bool oneMissing = what.find("required") != std::string::npos && what.find(" 1 ") != std::string::npos;
    for (auto a = args.rbegin(); a != args.rend(); ++a)
      if (!a->empty() && (*a)[0] == '-' && app_->get_option_no_throw(a->substr(0, a->find('='))) != nullptr)
        throw UsageError{*a + " needs " + (oneMissing ? "a value" : "more values") + seeHelp};
    throw UsageError{what + seeHelp};
  } catch (const CLI::ParseError& e) {
    throw UsageError{std::string(e.what()) + seeHelp};
  }
  if (input_ != nullptr) {
    if (inputs_.size() > 1)
      throw UsageError{"more than one " + inputWhat_ + " given ('" + inputs_[0] + "', '" + inputs_[1] + "')"};
    if (!inputs_.empty()) *input_ = inputs_[0];
  }
}

uint64_t CommandLine::parseWhole(const std::string& flag, const std::string& v, uint64_t lo, uint64_t hi) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
  // strtoull skips blanks and accepts a sign: only plain digits are a whole number here.
  if (v.empty() || !std::isdigit(static_cast<unsigned char>(v[0])) || *end != '\0' || errno == ERANGE || n < lo ||
      n > hi)
    throw UsageError{flag + " expects a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got '" + v + "'"};
  return n;
}

double CommandLine::parseNumber(const std::string& flag, const std::string& v) {
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(d)) throw UsageError{flag + " expects a number, got '" + v + "'"};
  return d;
}

void CommandLine::parsePoint(const std::string& flag, const std::string& v, double out[3]) {
  auto bad = [&]() {
    return UsageError{flag + " expects a point x,y,z (three numbers separated by commas, e.g. " + flag +
                      " 0,0.5,1), got '" + v + "'"};
  };
  size_t from = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t comma = v.find(',', from);
    if ((k < 2) != (comma != std::string::npos)) throw bad();
    std::string part = v.substr(from, k < 2 ? comma - from : std::string::npos);
    const size_t first = part.find_first_not_of(" \t");
    const size_t last = part.find_last_not_of(" \t");
    if (first == std::string::npos) throw bad();
    part = part.substr(first, last - first + 1);
    char* end = nullptr;
    const double d = std::strtod(part.c_str(), &end);
    if (*end != '\0' || !std::isfinite(d)) throw bad();
    out[k] = d;
    from = comma + 1;
  }
}

}  // namespace fgsg::cli
