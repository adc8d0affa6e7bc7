// The string of a parallel (L-system) derivation: 16 bytes per module (the op that made
// it, where its arguments start in one pool, its random key), with everything that is
// the same for every module an op makes — its kind, symbol, argument count, position
// among its successor's symbols, the symbol whose rule holds it, how it is rewritten —
// in a table by op id (StringOps), looked up instead of stored.
#pragma once

#include "ir/ir.h"
#include "backend/engine/string_storage_pool.h"
#include "ir/program_layout.h"
#include "runtime/mesh_array.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <new>
#include <vector>

namespace fgsg::backend {

// One module: a shape symbol or a command.
struct StringModule {
  uint32_t op = 0;        // op id (ir::ProgramLayout): StringOps says what it is
  uint32_t firstArg = 0;  // its arguments in the string's pool
  uint64_t key = 0;       // a symbol's random key (0 for commands)
};
static_assert(sizeof(StringModule) == 16);

// A growing array that is not cleared or value-initialised: a step's string is written
// over the buffer of the string two steps before (double buffering), and the parallel
// writer fills a resized array in place. Its storage is rt::MeshArray's: from 4 MiB on,
// asked for transparent huge pages, because the kernel's fault per fresh 4 KiB page was
// most of a large step's time (a 25 MB string: 6 000 faults, each a trap to the
// hypervisor on a VM); large blocks are kept for the next derivation (StringStoragePool).
template <typename T>
class StringBuffer {
 public:
  StringBuffer() = default;
  StringBuffer(const StringBuffer&) = delete;
  StringBuffer& operator=(const StringBuffer&) = delete;
  StringBuffer(StringBuffer&& o) noexcept { swap(o); }
  StringBuffer& operator=(StringBuffer&& o) noexcept {
    swap(o);
    return *this;
  }
  ~StringBuffer() { release(); }
  void swap(StringBuffer& o) noexcept {
    std::swap(data_, o.data_), std::swap(size_, o.size_), std::swap(capacity_, o.capacity_);
  }

  size_t size() const { return size_; }
  size_t capacity() const { return capacity_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  void clear() { size_ = 0; }
  void push_back(const T& v) {
    if (size_ == capacity_) grow(size_ + 1);
    data_[size_++] = v;
  }
  // Appends n values; returns where they go.
  T* extend(size_t n) {
    if (n > capacity_ - size_) grow(n > kMaxElements ? SIZE_MAX : size_ + n);
    T* at = data_ + size_;
    size_ += n;
    return at;
  }
  void append(const T* v, size_t n) {
    if (n) std::memcpy(extend(n), v, n * sizeof(T));
  }
  // Sizes the array to n; new elements are left unset, for the caller to write.
  void resizeForOverwrite(size_t n) {
    if (n > capacity_) grow(n);
    size_ = n;
  }
  void truncate(size_t n) { size_ = n < size_ ? n : size_; }
  // Room for n elements at least, in one allocation: pages not yet written cost nothing.
  void reserve(size_t n) {
    if (n > capacity_) reallocate(n);
  }

 private:
  void grow(size_t need) {
    if (need > kMaxElements) throw std::bad_alloc();
    size_t cap = capacity_ ? capacity_ : 64;
    while (cap < need) cap += cap / 2 + 64;
    reallocate(std::min(cap, kMaxElements));
  }
  // Past kMaxElements, cap * sizeof(T) (and its rounding up to huge pages) would wrap to a
  // small block taken for a huge one: out of memory (R020) instead, the buffer unchanged.
  void reallocate(size_t cap) {
    if (cap > kMaxElements) throw std::bad_alloc();
    size_t granted = 0;
    T* bigger = static_cast<T*>(StringStoragePool::instance().take(cap * sizeof(T), granted));
    if (size_) std::memcpy(bigger, data_, size_ * sizeof(T));
    release();
    data_ = bigger;
    capacity_ = granted / sizeof(T);
  }
  void release() noexcept {
    if (data_) StringStoragePool::instance().giveBack(data_, capacity_ * sizeof(T));
    data_ = nullptr;
  }

  static constexpr size_t kMaxElements = SIZE_MAX / 2 / sizeof(T);  // half the address space

  T* data_ = nullptr;
  size_t size_ = 0, capacity_ = 0;
};

// A string: its modules and their arguments.
struct ModuleString {
  StringBuffer<StringModule> modules;
  StringBuffer<double> args;
  size_t size() const { return modules.size(); }
  void clear() { modules.clear(), args.clear(); }
  void swap(ModuleString& other) noexcept { modules.swap(other.modules), args.swap(other.args); }
  void append(uint32_t op, uint64_t key, const double* a, uint32_t n) {
    modules.push_back({op, static_cast<uint32_t>(args.size()), key});
    args.append(a, n);
  }
};

// How a module is rewritten in a step.
enum class Rewrite : uint8_t {
  Keep,      // a command, or a symbol without rules: copied
  Template,  // one successor, always the same modules with the same arguments
  General,   // rule choice, guards, context, arguments computed per module
};

// What every module made by one op shares.
struct StringOp {
  const ir::Op* op = nullptr;
  ir::OpKind kind = ir::OpKind::Push;
  uint32_t argCount = 0;    // arguments it holds
  uint32_t childIndex = 0;  // a symbol: its position among its successor's symbols (Shape.index)
  uint32_t owner = UINT32_MAX;  // the symbol whose rule holds it (UINT32_MAX: the axiom)
  Rewrite rewrite = Rewrite::Keep;
  int8_t draws = -1;        // a symbol F, f, + ...: the turtle command it is read as (ir::TurtleOp)
  bool contextSymbol = false;  // a symbol that context matching sees (not in #ignore)
  uint32_t successor = 0;   // Template: its index in StringOps::templates
  int8_t query = -1;        // a query module ?P ?H ?U ?L: which (QueryModule, query_modules.h)
};

// A successor that is the same for every module it rewrites: a rule of its own (no
// other rule, guard or context), one branch, and arguments fixed for the derivation.
// Rewriting is then copying its modules and arguments; a symbol's key is derived from
// the rewritten module's with its own salt (rt::childKey).
struct SuccessorTemplate {
  uint32_t rule = 0;
  std::vector<uint32_t> ops;          // op ids, in order
  std::vector<uint32_t> firstArg;     // per module: its first argument in args
  std::vector<double> args;
  std::vector<uint64_t> keySalt;      // per module: rt::childSalt of its position
  std::vector<uint64_t> keyMask;      // per module: ~0 for a symbol, 0 for a command (no key)
};

// The per-op table of a grammar's parallel derivation.
struct StringOps {
  std::vector<StringOp> ops;  // by op id
  std::vector<SuccessorTemplate> templates;
  bool allTemplates = false;  // no symbol needs General: a step can be split over threads
  bool hasCut = false;        // the grammar writes % somewhere
  bool hasContext = false;    // some rule has a left or right context
  bool hasQuery = false;      // a query module ?P ?H ?U ?L is written somewhere

  const StringOp& operator[](uint32_t op) const { return ops[op]; }
};

// Fills the table for `m` numbered by `layout`; `store(e, out, asSlots)` writes the value
// of a fixed expression: its parameter slots (a symbol's argument) or one number.
StringOps planString(const ir::Module& m, const ir::ProgramLayout& layout,
                     const std::function<void(const ir::Expr&, double*, bool)>& store);

// Whether a string can hold the modules `op` makes: symbols, scope and turtle commands,
// plain instances (Derivation::checkParallelOp says why the others cannot).
bool stringHolds(const ir::Op& op);

// Whether `e` has one value for the whole derivation: constants and attributes, and
// what is computed from them alone.
bool isFixed(const ir::Expr& e);

// A parallel derivation's next string, which a successor's modules are appended to.
struct StringTarget {
  ModuleString* out;
  uint64_t key;     // the rewritten module's key (its children's keys derive from it)
  uint32_t owner;   // the symbol rewritten (UINT32_MAX: the axiom)
  // The rewritten module's parameter slots: an instance its successor places records
  // them (Shape.params in --instances), as a sequential derivation's do.
  const double* ownerParams = nullptr;
  uint32_t ownerParamCount = 0;
};

}  // namespace fgsg::backend
