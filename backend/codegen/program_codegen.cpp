// The program's skeleton: its functions (every block's first, then each rule's guard and
// non-constant probabilities, then the direct symbols') and the FgsgProgram constant
// that lists them (runtime/abi.h). What each kind of function holds is emitted in a
// file of its own (program_codegen_internal.h); program_object.cpp compiles the module.
#include "backend/codegen/program_codegen.h"

#include "backend/codegen/program_codegen_internal.h"
#include "runtime/abi.h"

#include <string>
#include <vector>

namespace fgsg::backend::codegen::detail {

ProgramCodegen::ProgramCodegen(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& o)
    : m_(out), c_(out.getContext()), b_(c_), ir_(m), opt_(o), layout_(ir::layoutProgram(m)) {
  declareRuntime(out);
  ptr_ = llvm::PointerType::getUnqual(c_);
}

void ProgramCodegen::run() {
  std::vector<llvm::Constant*> blocks, guards, weights;
  for (uint32_t id = 0; id < layout_.blocks.size(); ++id) blocks.push_back(block(id));
  for (size_t r = 0; r < ir_.rules.size(); ++r) {
    const ir::Rule& rule = ir_.rules[r];
    guards.push_back(rule.hasGuard ? value(rule.guard, "fgsg_guard_" + std::to_string(r)) : nullPtr());
    for (size_t a = 0; a < rule.alternatives.size(); ++a) {
      const ir::Expr& p = rule.alternatives[a].probability;
      weights.push_back(p.isConst() ? nullPtr()
                                    : value(p, "fgsg_weight_" + std::to_string(r) + "_" + std::to_string(a)));
    }
  }
  std::vector<bool> places;
  const std::vector<bool> isDirect = findDirectSymbols(ir_, places);
  directFns_.assign(ir_.symbols.size(), nullptr);
  auto* directType = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, ptr_, ptr_, b_.getInt64Ty(), b_.getInt32Ty(), ptr_}, false);
  for (size_t s = 0; s < ir_.symbols.size(); ++s)
    if (isDirect[s])
      directFns_[s] = llvm::Function::Create(directType, llvm::Function::InternalLinkage,
                                             "fgsg_direct_" + ir_.symbols[s].name, m_);
  std::vector<llvm::Constant*> direct, placing;
  for (size_t s = 0; s < ir_.symbols.size(); ++s) {
    if (directFns_[s]) directSymbol(static_cast<uint32_t>(s));
    direct.push_back(directFns_[s] ? static_cast<llvm::Constant*>(directFns_[s]) : nullPtr());
    placing.push_back(b_.getInt8(isDirect[s] && places[s] ? 1 : 0));
  }
  table(blocks, guards, weights, direct, placing);
}

// A guard or probability: an expression function of its own, internal to the unit.
llvm::Function* ProgramCodegen::value(const ir::Expr& e, const std::string& name) {
  llvm::Function* f = emitExpr(m_, e, name);
  f->setLinkage(llvm::GlobalValue::InternalLinkage);
  return f;
}

llvm::Constant* ProgramCodegen::array(const std::vector<llvm::Constant*>& items, const char* name) {
  if (items.empty()) return nullPtr();
  auto* type = llvm::ArrayType::get(ptr_, items.size());
  return new llvm::GlobalVariable(m_, type, true, llvm::GlobalValue::PrivateLinkage,
                                  llvm::ConstantArray::get(type, items), name);
}

llvm::Constant* ProgramCodegen::string(const std::string& s, const char* name) {
  auto* init = llvm::ConstantDataArray::getString(c_, s, true);
  return new llvm::GlobalVariable(m_, init->getType(), true, llvm::GlobalValue::PrivateLinkage, init, name);
}

// The FgsgProgram constant (runtime/abi.h), field for field.
void ProgramCodegen::table(const std::vector<llvm::Constant*>& blocks,
                           const std::vector<llvm::Constant*>& guards,
                           const std::vector<llvm::Constant*>& weights,
                           const std::vector<llvm::Constant*>& direct,
                           const std::vector<llvm::Constant*>& placing) {
  llvm::Type* i32 = b_.getInt32Ty();
  auto* type = llvm::StructType::get(c_, {i32, i32, ptr_, i32, ptr_, i32, ptr_, ptr_, ptr_, i32, ptr_, ptr_, i32, ptr_});
  llvm::Constant* placingArray = nullPtr();
  if (!placing.empty()) {
    auto* bytes = llvm::ArrayType::get(b_.getInt8Ty(), placing.size());
    placingArray = new llvm::GlobalVariable(m_, bytes, true, llvm::GlobalValue::PrivateLinkage,
                                            llvm::ConstantArray::get(bytes, placing), "fgsg_direct_places");
  }
  auto count = [&](size_t n) { return llvm::ConstantInt::get(i32, n); };
  llvm::Constant* init = llvm::ConstantStruct::get(
      type, {count(FGSG_ABI_VERSION), count(blocks.size()), array(blocks, "fgsg_blocks"),
             count(guards.size()), array(guards, "fgsg_guards"), count(weights.size()),
             array(weights, "fgsg_weights"),
             opt_.embedSource ? string(opt_.source, "fgsg_source") : nullPtr(),
             opt_.embedSource ? string(opt_.sourceName, "fgsg_source_name") : nullPtr(),
             count(direct.size()), array(direct, "fgsg_direct"), placingArray, count(sizeof(rt::Scope)),
             opt_.embedSource && !opt_.startRule.empty() ? string(opt_.startRule, "fgsg_start_rule") : nullPtr()});
  new llvm::GlobalVariable(m_, type, true, llvm::GlobalValue::ExternalLinkage, init, opt_.tableSymbol);
}

}  // namespace fgsg::backend::codegen::detail

namespace fgsg::backend::codegen {

void emitProgram(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& options) {
  detail::ProgramCodegen(out, m, options).run();
}

}  // namespace fgsg::backend::codegen
