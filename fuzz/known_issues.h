// Inputs that reach bugs already known and being fixed elsewhere (../shared/repro, issues
// #11 and #24): the fuzzers skip them so that their runs find new problems instead of
// rediscovering these. Each filter names its reproducer; delete it once the fix lands.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fgsg::fuzz {

// False when FGSG_FUZZ_ALL_INPUTS=1: every filter below lets everything through, to check
// that the fixes have landed.
bool filtersOn();

// `derive parallel 4294967297` (repro parallel_int_overflow): a count past the int range
// is cast from double in sema (E999 / UBSan float-cast-overflow).
bool hasOverflowingParallelCount(std::string_view text);

// Paths into /dev (repro 16): /dev/zero and friends are read forever.
bool namesDeviceFile(std::string_view text);

// A number literal of magnitude 1e6 or more (repro 14/15 far points, scale_huge
// non-finite output, 4294967297-style counts): results overflow to inf or index out of
// range in code others are fixing. Only the whole-run target applies it.
bool hasHugeNumber(std::string_view text);

// OFF/PLY headers whose counts exceed what the file can hold (repro 05-08: bad_alloc), or
// an OFF face line with a negative corner count (repro 09: the reader hangs).
bool hasImpossibleMeshCounts(std::string_view text);

// A PLY "format" line whose version is not 1.0 (tests/reliability/fuzz_findings.sh): the
// header check lets it through and OpenMesh's PLY reader loops forever on it.
bool hasUnreadablePlyVersion(std::string_view text);

// An OBJ face corner without a vertex index ("f /1 /2 /3", tests/reliability/
// fuzz_findings.sh): OpenMesh's OBJ reader asserts (abort).
bool hasObjCornerWithoutVertex(std::string_view text);

}  // namespace fgsg::fuzz
