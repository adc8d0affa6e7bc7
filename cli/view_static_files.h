// The files of fgsg view's page, read once at start into memory: the server answers a
// request's path by exact lookup in this list, so no path from a request ever reaches the
// filesystem (no "..", "//", absolute paths, encodings or symlinks to get wrong).
#pragma once

#include <map>
#include <string>

namespace fgsg::cli {

class ViewStaticFiles {
 public:
  struct File {
    std::string contentType;
    std::string body;
  };

  // Reads the page's folder: regular files (symlinks are skipped) with a page's
  // extensions (.html .js .mjs .css .png .woff2 .json), at most 64 of them and 32 MiB in
  // all. False with a message.
  bool load(const std::string& dir, std::string& error);
  // The file for a request's resource ("/", "/index.html", "/three/build/three.module.js"
  // with any ?query); null for everything else.
  const File* find(const std::string& resource) const;
  size_t count() const { return files_.size(); }

 private:
  std::map<std::string, File> files_;  // by URL path: "/index.html"
};

}  // namespace fgsg::cli
