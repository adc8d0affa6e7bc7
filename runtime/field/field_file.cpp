#include "runtime/field/field_file.h"

#include "runtime/io/atomic_file.h"
#include "runtime/io/quoted_text.h"
#include "runtime/io/read_input.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace fgsg::rt::field {

namespace {

constexpr const char* kMagic = "fgsg-field";
constexpr int kVersion = 1;
constexpr const char* kHeaderForm = "fgsg-field 1 vector|tensor|asymmetric <vertexCount> [world|frame]";
constexpr const char* kScalarHeaderForm = "fgsg-field 1 scalar <vertexCount>";

// The whitespace-separated words of a line, comments removed.
std::vector<std::string_view> words(std::string_view line) {
  const size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool parseNumber(std::string_view word, double& value) {
  const char* end = word.data() + word.size();
  const char* begin = word.data();
  if (begin != end && *begin == '+') ++begin;  // from_chars takes no leading '+'
  auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end;
}

std::string at(const std::string& name, int line) {
  return name + ":" + std::to_string(line) + ": ";
}

enum class FileKind { Vector, Tensor, Asymmetric };

// Values per line for each kind and coordinate system.
int valuesPerLine(FileKind kind, FieldCoordinates c) {
  const bool world = c == FieldCoordinates::World;
  switch (kind) {
    case FileKind::Vector: return world ? 3 : 2;
    case FileKind::Tensor: return world ? 6 : 3;
    case FileKind::Asymmetric: return world ? 9 : 4;
  }
  return 0;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

bool parseField(std::string_view text, const std::string& name,
                std::shared_ptr<const TangentFrames> frames, std::optional<TangentField>& out,
                std::string& error) {
  const size_t nv = frames->vertexCount();
  bool haveHeader = false, tensor = false;
  FileKind kind = FileKind::Vector;
  FieldCoordinates coordinates = FieldCoordinates::World;
  int perLine = 0, lineNumber = 0;
  size_t vertex = 0;
  std::vector<Vec2> vectors;
  std::vector<Mat2> tensors;
  std::vector<double> rotations;  // asymmetric tensors' rotational parts
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto w = words(line);
    if (w.empty()) continue;
    if (!haveHeader) {
      double count = 0;
      if (w[0] != kMagic || w.size() < 4 || w.size() > 5) {
        error = at(name, lineNumber) + "expected the header '" + kHeaderForm + "'";
        return false;
      }
      if (w[1] != "1") {
        error = at(name, lineNumber) + "unsupported version " + io::quoteText(w[1]) +
                " (this reader knows " + std::to_string(kVersion) + ")";
        return false;
      }
      if (w[2] != "vector" && w[2] != "tensor" && w[2] != "asymmetric") {
        error = at(name, lineNumber) + "expected 'vector', 'tensor' or 'asymmetric', got " +
                io::quoteText(w[2]) + (w[2] == "scalar" ? " (a scalar field is read by `scalar(\"...\")`)" : "");
        return false;
      }
      kind = w[2] == "vector" ? FileKind::Vector : w[2] == "tensor" ? FileKind::Tensor : FileKind::Asymmetric;
      tensor = kind != FileKind::Vector;
      if (!parseNumber(w[3], count) || count < 0 || count != std::floor(count)) {
        error = at(name, lineNumber) + "expected a vertex count, got " + io::quoteText(w[3]);
        return false;
      }
      if (size_t(count) != nv) {
        error = at(name, lineNumber) + "the field has " + number(count) +
                " vertices, the surface " + std::to_string(nv);
        return false;
      }
      if (w.size() == 5) {
        if (w[4] != "world" && w[4] != "frame") {
          error = at(name, lineNumber) + "expected 'world' or 'frame', got " +
                  io::quoteText(w[4]);
          return false;
        }
        coordinates = w[4] == "world" ? FieldCoordinates::World : FieldCoordinates::Frame;
      }
      perLine = valuesPerLine(kind, coordinates);
      haveHeader = true;
      if (tensor)
        tensors.reserve(nv);
      else
        vectors.reserve(nv);
      continue;
    }
    if (vertex >= nv) {
      error = at(name, lineNumber) + "more vertex lines than the " + std::to_string(nv) +
              " the header announces";
      return false;
    }
    if (int(w.size()) != perLine) {
      error = at(name, lineNumber) + "expected " + std::to_string(perLine) + " numbers, got " +
              std::to_string(w.size());
      return false;
    }
    double x[9];
    for (int i = 0; i < perLine; ++i) {
      if (!parseNumber(w[i], x[i])) {
        error = at(name, lineNumber) + io::quoteText(w[i]) + " is not a number";
        return false;
      }
      if (!std::isfinite(x[i])) {
        error = at(name, lineNumber) + "value " + std::to_string(i + 1) + " is not finite (" +
                io::clipText(w[i]) + ")";
        return false;
      }
    }
    const Frame& frame = frames->vertexFrame(int(vertex));
    if (kind == FileKind::Asymmetric) {
      // The whole 3x3 (or 2x2) tensor, restricted to the tangent plane: its symmetric
      // and rotational parts.
      Mat2 t;
      if (coordinates == FieldCoordinates::World) {
        Mat3 T;
        T << x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8];
        Eigen::Matrix<double, 3, 2> E;
        E << frame.e1, frame.e2;
        t = E.transpose() * T * E;
      } else {
        t << x[0], x[1], x[2], x[3];
      }
      tensors.push_back(0.5 * (t + t.transpose()));
      rotations.push_back(0.5 * (t(1, 0) - t(0, 1)));
    } else if (tensor) {
      Mat2 t;
      if (coordinates == FieldCoordinates::World) {
        Mat3 T;
        T << x[0], x[1], x[2], x[1], x[3], x[4], x[2], x[4], x[5];
        t = frame.tensorToLocal(T);
      } else {
        t << x[0], x[1], x[1], x[2];
      }
      tensors.push_back(t);
    } else {
      vectors.push_back(coordinates == FieldCoordinates::World
                            ? frame.toLocal(Vec3(x[0], x[1], x[2]))
                            : Vec2(x[0], x[1]));
    }
    ++vertex;
  }
  if (!haveHeader) {
    error = name + ": empty field file (expected the header '" + kHeaderForm + "')";
    return false;
  }
  if (vertex != nv) {
    error = name + ": expected " + std::to_string(nv) + " vertex lines, got " +
            std::to_string(vertex);
    return false;
  }
  out.emplace(std::move(frames), tensor ? FieldType::Tensor : FieldType::Vector);
  if (tensor)
    out->setVertexTensors(std::move(tensors));
  else
    out->setVertexVectors(std::move(vectors));
  if (kind == FileKind::Asymmetric) out->setVertexRotations(std::move(rotations));
  return true;
}

bool loadField(const std::string& path, std::shared_ptr<const TangentFrames> frames,
               std::optional<TangentField>& out, std::string& error) {
  std::string text;
  if (!io::readInputFile(path, "a field file", text, error)) return false;
  return parseField(text, path, std::move(frames), out, error);
}

bool parseScalarField(std::string_view text, const std::string& name, size_t vertexCount, ScalarField& out,
                      std::string& error) {
  bool haveHeader = false;
  int lineNumber = 0;
  out.values.clear();
  for (size_t pos = 0; pos <= text.size();) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    const auto w = words(text.substr(pos, eol - pos));
    pos = eol + 1;
    ++lineNumber;
    if (w.empty()) continue;
    if (!haveHeader) {
      double count = 0;
      if (w.size() != 4 || w[0] != "fgsg-field" || w[1] != "1" || w[2] != "scalar" || !parseNumber(w[3], count) ||
          count < 0 || count != std::floor(count)) {
        error = at(name, lineNumber) + "expected the header '" + kScalarHeaderForm + "'";
        return false;
      }
      if (size_t(count) != vertexCount) {
        error = at(name, lineNumber) + "the field has " + number(count) + " vertices, the surface " +
                std::to_string(vertexCount);
        return false;
      }
      haveHeader = true;
      out.values.reserve(vertexCount);
      continue;
    }
    double v = 0;
    if (w.size() != 1 || !parseNumber(w[0], v)) {
      error = at(name, lineNumber) + "expected one number, got " + io::quoteText(w[0]) +
              (w.size() > 1 ? " and " + std::to_string(w.size() - 1) + " more" : "");
      return false;
    }
    if (!std::isfinite(v)) {
      error = at(name, lineNumber) + "the value is not finite (" + io::clipText(w[0]) + ")";
      return false;
    }
    if (out.values.size() == vertexCount) {
      error = at(name, lineNumber) + "more vertex lines than the " + std::to_string(vertexCount) +
              " the header announces";
      return false;
    }
    out.values.push_back(v);
  }
  if (!haveHeader) {
    error = name + ": empty field file (expected the header '" + kScalarHeaderForm + "')";
    return false;
  }
  if (out.values.size() != vertexCount) {
    error = name + ": expected " + std::to_string(vertexCount) + " vertex lines, got " +
            std::to_string(out.values.size());
    return false;
  }
  return true;
}

bool loadScalarField(const std::string& path, size_t vertexCount, ScalarField& out, std::string& error) {
  std::string text;
  if (!io::readInputFile(path, "a field file", text, error)) return false;
  return parseScalarField(text, path, vertexCount, out, error);
}

std::string formatField(const TangentField& field, FieldCoordinates coordinates) {
  const bool world = coordinates == FieldCoordinates::World;
  const char* kind = field.isAsymmetric() ? "asymmetric" : field.isTensor() ? "tensor" : "vector";
  const char* layout = field.isAsymmetric() ? (world ? "world xx xy xz yx yy yz zx zy zz" : "frame t11 t12 t21 t22")
                       : field.isTensor()   ? (world ? "world xx xy xz yy yz zz" : "frame t11 t12 t22")
                                            : (world ? "world x y z" : "frame u v");
  std::string s;
  s += std::string("# ") + kind + " field, one line per vertex (" + layout + ")\n";
  s += std::string(kMagic) + " " + std::to_string(kVersion) + " " + kind + " " +
       std::to_string(field.vertexCount()) + (world ? " world" : " frame") + "\n";
  for (size_t v = 0; v < field.vertexCount(); ++v) {
    std::vector<double> x;
    if (field.isAsymmetric()) {
      if (world) {
        const Mat3 T = field.vertexAsymmetricWorld(int(v));
        x = {T(0, 0), T(0, 1), T(0, 2), T(1, 0), T(1, 1), T(1, 2), T(2, 0), T(2, 1), T(2, 2)};
      } else {
        const Mat2& t = field.vertexTensor(int(v));
        const double r = field.vertexRotation(int(v));
        x = {t(0, 0), t(0, 1) - r, t(1, 0) + r, t(1, 1)};
      }
    } else if (field.isTensor()) {
      if (world) {
        const Mat3 T = field.vertexTensorWorld(int(v));
        x = {T(0, 0), T(0, 1), T(0, 2), T(1, 1), T(1, 2), T(2, 2)};
      } else {
        const Mat2& t = field.vertexTensor(int(v));
        x = {t(0, 0), t(0, 1), t(1, 1)};
      }
    } else if (world) {
      const Vec3 w = field.vertexVectorWorld(int(v));
      x = {w.x(), w.y(), w.z()};
    } else {
      x = {field.vertexVector(int(v)).x(), field.vertexVector(int(v)).y()};
    }
    for (size_t i = 0; i < x.size(); ++i) {
      if (i) s += ' ';
      s += number(x[i]);
    }
    s += '\n';
  }
  return s;
}

bool saveField(const std::string& path, const TangentField& field, std::string& error,
               FieldCoordinates coordinates) {
  return io::writeFileAtomically(path, formatField(field, coordinates), error);
}

}  // namespace fgsg::rt::field
