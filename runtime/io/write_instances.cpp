#include "runtime/io/write_instances.h"

#include "runtime/io/json_text.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <new>

namespace fgsg::rt::io {

namespace {

template <typename Range, typename Append>
void appendArray(std::string& out, const Range& items, Append append) {
  out += '[';
  bool first = true;
  for (const auto& item : items) {
    if (!first) out += ',';
    first = false;
    append(out, item);
  }
  out += ']';
}

// An index that does not name an entry of its table is written as null.
void appendName(std::string& out, const std::vector<std::string>& table, uint32_t index) {
  if (index < table.size())
    appendJsonString(out, table[index]);
  else
    out += "null";
}

// Parameters as their kinds say: numbers, true/false, the string's text, [x,y,z].
void appendParams(std::string& out, const InstanceList& list, const Instance& inst) {
  static const std::vector<ParamKind> kNone;
  const auto& kinds = inst.symbol < list.paramKinds.size() ? list.paramKinds[inst.symbol] : kNone;
  auto slot = [&](uint32_t k) {
    const size_t at = size_t(inst.firstParam) + k;
    return k < inst.paramCount && at < list.params.size() ? list.params[at] : NAN;
  };
  uint32_t k = 0;
  for (size_t p = 0; k < inst.paramCount; ++p) {
    if (p) out += ',';
    const ParamKind kind = p < kinds.size() ? kinds[p] : ParamKind::Number;
    const double v = slot(k);
    switch (kind) {
      case ParamKind::Number: appendJsonNumber(out, v); k += 1; break;
      case ParamKind::Boolean: out += v != 0 ? "true" : "false"; k += 1; break;
      case ParamKind::String:
        if (v >= 0 && v < double(list.strings.size()))
          appendJsonString(out, list.strings[size_t(v)]);
        else
          out += "null";
        k += 1;
        break;
      case ParamKind::Vector:
        out += '[';
        for (int c = 0; c < 3; ++c) {
          if (c) out += ',';
          appendJsonNumber(out, slot(k + c));
        }
        out += ']';
        k += 3;
        break;
    }
  }
}

}  // namespace

std::string assetNameFrom(const std::string& asset, const std::string& folder) {
  namespace fs = std::filesystem;
  const fs::path path(asset);
  if (folder.empty() || !path.is_absolute()) return asset;
  std::error_code ec;
  // Both resolved the same way (symbolic links followed as far as the paths exist), so that
  // /tmp and its real name do not part them.
  const fs::path from = fs::weakly_canonical(fs::absolute(folder, ec), ec);
  const fs::path to = fs::weakly_canonical(path, ec);
  const fs::path relative = to.lexically_relative(from);
  return relative.empty() ? asset : relative.generic_string();
}

std::string encodeInstancesJson(const InstanceList& list, const std::string& folder) {
  std::string out = "{\"format\":\"fgsg-instances\",\"version\":1,\n\"assets\":";
  std::vector<std::string> assets = list.assets;
  for (std::string& a : assets) a = assetNameFrom(a, folder);
  appendArray(out, assets, appendJsonString);
  out += ",\n\"symbols\":";
  appendArray(out, list.symbols, appendJsonString);
  out += ",\n\"instances\":[";
  for (size_t i = 0; i < list.instances.size(); ++i) {
    const Instance& inst = list.instances[i];
    out += i == 0 ? "\n" : ",\n";
    out += "{\"asset\":";
    appendName(out, assets, inst.asset);
    out += ",\"symbol\":";
    appendName(out, list.symbols, inst.symbol);
    out += ",\"transform\":";
    appendArray(out, inst.transform, appendJsonNumber<double>);
    out += ",\"color\":";
    appendArray(out, inst.color, appendJsonNumber<float>);
    out += ",\"params\":[";
    appendParams(out, list, inst);
    out += "]}";
  }
  out += "\n]}\n";
  return out;
}

bool stageInstancesJson(const InstanceList& list, const std::string& path, OutputTransaction& outputs,
                        std::string& error) {
  for (size_t i = 0; i < list.instances.size(); ++i) {
    const Instance& inst = list.instances[i];
    const bool finite = std::all_of(inst.transform.begin(), inst.transform.end(), [](double v) { return std::isfinite(v); }) &&
                        std::all_of(inst.color.begin(), inst.color.end(), [](float v) { return std::isfinite(v); });
    if (!finite) {
      error = "cannot write '" + path + "': instance " + std::to_string(i) + " (symbol '" +
              (inst.symbol < list.symbols.size() ? list.symbols[inst.symbol] : std::string("?")) +
              "') has a transform or colour that is not finite";
      return false;
    }
  }
  std::string bytes;
  try {
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::absolute(path, ec).parent_path();
    bytes = encodeInstancesJson(list, folder.string());
  } catch (const std::bad_alloc&) {
    error = "cannot write '" + path + "': out of memory while encoding " + std::to_string(list.instances.size()) +
            " instances";
    return false;
  }
  return outputs.stage(path, bytes, error);
}

std::string encodeLinesJson(const InstanceList& list) {
  std::string out = "{\"format\":\"fgsg-lines\",\"version\":1,\n\"lines\":[";
  for (size_t i = 0; i < list.lines.size(); ++i) {
    const LinePath& line = list.lines[i];
    out += i ? ",\n{\"symbol\":" : "\n{\"symbol\":";
    appendName(out, list.symbols, line.symbol);
    out += ",\"width\":";
    appendJsonNumber(out, line.width);
    out += line.merge ? ",\"merge\":true,\"points\":" : ",\"merge\":false,\"points\":";
    appendArray(out, line.points, [](std::string& o, const std::array<double, 3>& p) {
      appendArray(o, p, [](std::string& oo, double v) { appendJsonNumber(oo, v); });
    });
    out += '}';
  }
  return out + "\n]}\n";
}

bool stageLinesJson(const InstanceList& list, const std::string& path, OutputTransaction& outputs, std::string& error) {
  std::string bytes;
  try {
    bytes = encodeLinesJson(list);
  } catch (const std::bad_alloc&) {
    error = "cannot write '" + path + "': out of memory while encoding " + std::to_string(list.lines.size()) + " lines";
    return false;
  }
  return outputs.stage(path, bytes, error);
}

bool writeInstancesJson(const InstanceList& list, const std::string& path, std::string& error) {
  OutputTransaction one;
  return stageInstancesJson(list, path, one, error) && one.commit(error);
}

std::string instanceParamsJson(const InstanceList& list, const Instance& inst) {
  std::string out = "[";
  appendParams(out, list, inst);
  return out + "]";
}

}  // namespace fgsg::rt::io
