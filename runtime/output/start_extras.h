// What a start shape's node carries in glTF `extras` (and what Python and the C API give
// as its extras): {"start": its number, "instances": how many it placed, "properties":
// the lot's feature properties, "attrs": the grammar attrs' values it derived with,
// "reports": its report collections by key as `fgsg run --report` writes them ({"values":
// [...], "count", and for numbers "sum", "average", "min", "max", "nnz"; for strings
// "strings": {value: count}})}; properties, attrs and reports only where it has some.
#pragma once

#include "runtime/output/scene.h"

#include <nlohmann/json.hpp>

namespace fgsg::rt::output {

nlohmann::json startExtras(const StartNode& start);

}  // namespace fgsg::rt::output
