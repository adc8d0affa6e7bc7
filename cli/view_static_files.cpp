#include "cli/view_static_files.h"

#include <filesystem>
#include <fstream>

namespace fgsg::cli {

namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxFiles = 64;
constexpr uintmax_t kMaxBytes = uintmax_t(32) << 20;

const char* contentType(const std::string& ext) {
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".woff2") return "font/woff2";
  if (ext == ".json") return "application/json";
  return nullptr;  // not a file of the page
}

}  // namespace

bool ViewStaticFiles::load(const std::string& dir, std::string& error) {
  files_.clear();
  std::error_code ec;
  uintmax_t total = 0;
  const fs::path root = fs::path(dir);
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    // symlink_status: a link is not followed, whatever it points at.
    if (!fs::is_regular_file(it->symlink_status(ec))) continue;
    const char* type = contentType(it->path().extension().string());
    if (!type) continue;
    const uintmax_t size = fs::file_size(it->path(), ec);
    if (ec) break;
    total += size;
    if (files_.size() >= kMaxFiles || total > kMaxBytes) {
      error = "the viewer's page folder " + dir + " holds more than " + std::to_string(kMaxFiles) + " files or " +
              std::to_string(kMaxBytes >> 20) + " MiB: is FGSG_VIEWER_DIR the page's folder?";
      return false;
    }
    std::string body(static_cast<size_t>(size), '\0');
    std::ifstream in(it->path(), std::ios::binary);
    if (!in.read(body.data(), static_cast<std::streamsize>(size))) {
      error = "cannot read " + it->path().string();
      return false;
    }
    files_["/" + it->path().lexically_relative(root).generic_string()] = File{type, std::move(body)};
  }
  if (ec) {
    error = "cannot read the viewer's page folder " + dir + ": " + ec.message();
    return false;
  }
  if (!files_.count("/index.html")) {
    error = "the viewer's page folder " + dir + " has no index.html";
    return false;
  }
  return true;
}

const ViewStaticFiles::File* ViewStaticFiles::find(const std::string& resource) const {
  std::string path = resource.substr(0, resource.find_first_of("?#"));
  if (path == "/") path = "/index.html";
  const auto it = files_.find(path);
  return it == files_.end() ? nullptr : &it->second;
}

}  // namespace fgsg::cli
