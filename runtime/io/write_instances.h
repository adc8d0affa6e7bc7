// Writes a derivation's instance list as JSON, for tools that place their own geometry:
//   {"format":"fgsg-instances","version":1,"assets":[...],"symbols":[...],
//    "instances":[{"asset":"torus","symbol":"B","transform":[16 numbers, column-major],
//                  "color":[r,g,b],"params":[...]}, ...]}
// Numbers are the shortest text that reads back as the same value, so the file is exact
// and deterministic; one instance per line keeps diffs readable. Non-finite numbers,
// which JSON cannot express, are written as null.
#pragma once

#include "runtime/instances.h"
#include "runtime/io/output_transaction.h"

#include <string>

namespace fgsg::rt::io {

// `folder`: where the file goes. Non-empty: an asset named by an absolute path (a `.cga`
// file's i() asset, which the front end finds beside the rule file or in an assets/ folder
// and makes absolute) is written relative to that folder, so that a pipeline can move the
// folder with its assets; names (`cube`, `builtin:cube`) and relative paths stay as written.
std::string encodeInstancesJson(const InstanceList& list, const std::string& folder = "");

// `asset` as the instances file in `folder` names it (see encodeInstancesJson).
std::string assetNameFrom(const std::string& asset, const std::string& folder);

// One instance's parameters as a JSON array, as the file writes them (fgsg view's picking).
std::string instanceParamsJson(const InstanceList& list, const Instance& inst);

// Checks that every transform and colour is finite (a file must not carry them as null),
// encodes (asset paths relative to `path`'s folder) and stages the file in `outputs`; false
// and a message naming `path` otherwise.
bool stageInstancesJson(const InstanceList& list, const std::string& path, OutputTransaction& outputs,
                        std::string& error);

// Stages and commits alone: replaces `path` atomically; false and a message on failure.
bool writeInstancesJson(const InstanceList& list, const std::string& path, std::string& error);

// The line graph (InstanceList::lines) as JSON, `fgsg run --lines`:
//   {"format":"fgsg-lines","version":1,"lines":[{"symbol":"A","width":0.05,"merge":true,
//    "points":[[x,y,z],...]}, ...]}
// one line per entry, in the order the lines started; a merged line's last point lies on
// the centreline of the line it joined.
std::string encodeLinesJson(const InstanceList& list);
bool stageLinesJson(const InstanceList& list, const std::string& path, OutputTransaction& outputs, std::string& error);

}  // namespace fgsg::rt::io
