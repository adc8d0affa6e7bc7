// The reports of a derivation (CGA's report(key, value), runtime/reports.h) as JSON,
// `fgsg run --report FILE`:
//   {"format":"fgsg-reports","version":1,
//    "starts":[{"start":0,"lot":{"feature":0,"part":0,"id":"L1"},
//               "reports":{"area":{"values":[60],"count":1,"sum":60,"average":60,"min":60,"max":60,"nnz":1},
//                          "style":{"values":["brick"],"count":1,"strings":{"brick":1}}}}, ...],
//    "all":{...the same collections over every start shape...}}
// One entry per start shape (each --lots lot, with the feature it came from; each seed
// derived apart; else the one axiom), even one without reports; keys sorted. Statistics
// (sum, average, min, max, nnz: values not 0) cover the numbers and booleans (true is 1)
// and appear when there is one; "strings" counts string values. Numbers are the shortest
// text that reads back as the same double (non-finite ones: null); one start per line.
#pragma once

#include "runtime/derivation.h"
#include "runtime/io/output_transaction.h"

#include <string>
#include <vector>

namespace fgsg::rt::io {

// `lots`: the run's --lots (empty: none), to name each start shape's lot.
std::string encodeReportsJson(const DeriveResult& result, const std::vector<Lot>& lots);

bool stageReportsJson(const DeriveResult& result, const std::vector<Lot>& lots, const std::string& path,
                      OutputTransaction& outputs, std::string& error);

}  // namespace fgsg::rt::io
