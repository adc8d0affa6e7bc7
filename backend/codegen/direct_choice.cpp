// Rule choice in direct code: Interpreter::choose for one shape, guards and weights
// evaluated inline. Decided in code when the weights are constant (chooseStatic),
// otherwise by candidate lists built at run time (chooseDynamic); both draw the same
// random numbers as the interpreter, in the same order.
#include "backend/codegen/program_codegen_internal.h"

#include <cmath>
#include <vector>

namespace fgsg::backend::codegen::detail {

// Weights all constant and valid, at most one rule with a guard: which alternatives
// are candidates depends only on that guard, so the choice is decided in code.
bool ProgramCodegen::constantChoice(const ir::Symbol& sym) const {
  int guarded = 0;
  for (uint32_t ri : sym.rules) {
    const ir::Rule& r = ir_.rules[ri];
    if (!choosable(r)) continue;
    guarded += r.hasGuard;
    for (const auto& alt : r.alternatives)
      if (!alt.probability.isConst() || !(alt.probability.num >= 0) || !std::isfinite(alt.probability.num))
        return false;
  }
  return guarded <= 1;
}

// Interpreter::choose with the candidate lists known: the guarded rule's positive
// alternatives when its guard holds, else those of the rules without a guard; with
// several, x = next() * total and the walk of pickCandidate over constant weights.
void ProgramCodegen::chooseStatic(const ir::Symbol& sym, llvm::Value* chosen, llvm::BasicBlock* apply) {
  struct Candidate {
    uint32_t alt;
    double weight;
  };
  auto pick = [&](const std::vector<Candidate>& list) {
    if (list.size() == 1) {
      b_.CreateStore(b_.getInt32(list[0].alt), chosen);
      b_.CreateBr(apply);
      return;
    }
    double total = 0;
    for (const auto& c : list) total += c.weight;
    llvm::Value* x = b_.CreateFMul(call("fgsg_rt_next", {ctx_}), llvm::ConstantFP::get(b_.getDoubleTy(), total));
    for (size_t i = 0; i + 1 < list.size(); ++i) {
      llvm::Value* w = llvm::ConstantFP::get(b_.getDoubleTy(), list[i].weight);
      llvm::BasicBlock* found = newBlock("found");
      llvm::BasicBlock* next = newBlock("walk_next");
      b_.CreateCondBr(b_.CreateFCmpOLT(x, w), found, next);
      b_.SetInsertPoint(found);
      b_.CreateStore(b_.getInt32(list[i].alt), chosen);
      b_.CreateBr(apply);
      b_.SetInsertPoint(next);
      x = b_.CreateFSub(x, w);
    }
    b_.CreateStore(b_.getInt32(list.back().alt), chosen);  // also when rounding leaves x beyond all
    b_.CreateBr(apply);
  };
  auto positive = [&](uint32_t ri, std::vector<Candidate>& list) {
    const ir::Rule& r = ir_.rules[ri];
    for (size_t a = 0; a < r.alternatives.size(); ++a)
      if (r.alternatives[a].probability.num > 0)
        list.push_back({layout_.firstAlternative[ri] + static_cast<uint32_t>(a), r.alternatives[a].probability.num});
  };
  std::vector<Candidate> general;
  for (uint32_t ri : sym.rules)
    if (choosable(ir_.rules[ri]) && !ir_.rules[ri].hasGuard) positive(ri, general);
  for (uint32_t ri : sym.rules) {
    const ir::Rule& r = ir_.rules[ri];
    if (!choosable(r) || !r.hasGuard) continue;
    std::vector<Candidate> specific;
    positive(ri, specific);
    llvm::Value* g = num(r.guard);  // evaluated in any case: it may draw random numbers
    if (!cannotFail(r.guard)) checkStop();
    if (specific.empty()) continue;  // a guard that holds still leaves no candidate
    llvm::BasicBlock* holds = newBlock("holds");
    llvm::BasicBlock* otherwise = newBlock("general");
    b_.CreateCondBr(b_.CreateFCmpUNE(g, zero()), holds, otherwise);
    b_.SetInsertPoint(holds);
    pick(specific);
    b_.SetInsertPoint(otherwise);
  }
  if (general.empty()) {  // no rule applies: the shape is terminal
    bump(kTerminals);
    b_.CreateBr(exit_);
    return;
  }
  pick(general);
}

// Interpreter::choose in general: candidates (global alternative index, weight)
// collected at run time, rules with a guard first, those without only when none
// applies; of a symbol that takes the first rule that applies, the first guarded one.
void ProgramCodegen::chooseDynamic(const ir::Symbol& sym, llvm::Value* chosen, llvm::BasicBlock* apply,
                                   size_t alternatives) {
  const size_t room = std::max<size_t>(alternatives, 1);
  llvm::Value* candAlt = frameSlots(b_.getInt32Ty(), room);
  llvm::Value* candWeight = frameSlots(b_.getDoubleTy(), room);
  llvm::Value* count = frameSlots(b_.getInt32Ty(), 1);
  llvm::Value* total = frameSlots(b_.getDoubleTy(), 1);
  b_.CreateStore(b_.getInt32(0), count);
  b_.CreateStore(zero(), total);
  for (int pass = 0; pass < 2; ++pass) {
    llvm::BasicBlock* passBlock = newBlock(pass == 0 ? "specific" : "general");
    llvm::BasicBlock* after = newBlock("collected");
    if (pass == 1)
      b_.CreateCondBr(b_.CreateICmpEQ(b_.CreateLoad(b_.getInt32Ty(), count), b_.getInt32(0)), passBlock, after);
    else
      b_.CreateBr(passBlock);
    b_.SetInsertPoint(passBlock);
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = ir_.rules[ri];
      if (!choosable(r) || r.hasGuard != (pass == 0)) continue;
      llvm::BasicBlock* next = newBlock("next_rule");
      if (r.hasGuard) {
        llvm::Value* g = num(r.guard);
        if (!cannotFail(r.guard)) checkStop();
        llvm::BasicBlock* holds = newBlock("holds");
        b_.CreateCondBr(b_.CreateFCmpUNE(g, zero()), holds, next);
        b_.SetInsertPoint(holds);
        // Only the first rule that applies is taken (ir::Symbol::firstApplicable); a
        // second one is an overlap, which the engine's own order reports (R029).
        if (sym.firstApplicable)
          giveUpIf(b_.CreateICmpNE(b_.CreateLoad(b_.getInt32Ty(), count), b_.getInt32(0)));
      }
      for (size_t a = 0; a < r.alternatives.size(); ++a) {
        const ir::Expr& weight = r.alternatives[a].probability;
        llvm::BasicBlock* skip = newBlock("no_candidate");
        llvm::Value* w = num(weight);
        if (weight.isConst()) {
          // Known now: an invalid weight always gives up, zero is never a candidate.
          if (!(weight.num >= 0) || !std::isfinite(weight.num)) {
            giveUpIf(b_.getTrue());
          } else if (weight.num == 0) {
            b_.CreateBr(skip);
            b_.SetInsertPoint(skip);
            continue;
          }
        } else {
          if (!cannotFail(weight)) checkStop();
          // R008 (a negative or non-finite weight) is the engine's to report.
          llvm::Value* finite = b_.CreateFCmpONE(b_.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, w),
                                                 llvm::ConstantFP::getInfinity(b_.getDoubleTy()));
          giveUpIf(b_.CreateNot(b_.CreateAnd(b_.CreateFCmpOGE(w, zero()), finite)));
          llvm::BasicBlock* positive = newBlock("candidate");
          b_.CreateCondBr(b_.CreateFCmpOGT(w, zero()), positive, skip);
          b_.SetInsertPoint(positive);
        }
        llvm::Value* n = b_.CreateLoad(b_.getInt32Ty(), count);
        b_.CreateStore(b_.getInt32(layout_.firstAlternative[ri] + static_cast<uint32_t>(a)),
                       b_.CreateInBoundsGEP(b_.getInt32Ty(), candAlt, n));
        b_.CreateStore(w, b_.CreateInBoundsGEP(b_.getDoubleTy(), candWeight, n));
        b_.CreateStore(b_.CreateAdd(n, b_.getInt32(1)), count);
        b_.CreateStore(b_.CreateFAdd(b_.CreateLoad(b_.getDoubleTy(), total), w), total);
        b_.CreateBr(skip);
        b_.SetInsertPoint(skip);
      }
      b_.CreateBr(next);
      b_.SetInsertPoint(next);
    }
    b_.CreateBr(after);
    b_.SetInsertPoint(after);
  }
  // No rule applies: the shape is terminal.
  llvm::Value* n = b_.CreateLoad(b_.getInt32Ty(), count);
  llvm::BasicBlock* terminal = newBlock("terminal");
  llvm::BasicBlock* rewrite = newBlock("rewrite");
  b_.CreateCondBr(b_.CreateICmpEQ(n, b_.getInt32(0)), terminal, rewrite);
  b_.SetInsertPoint(terminal);
  bump(kTerminals);
  b_.CreateBr(exit_);
  // One candidate takes no random number; several: x = next() * total, then the walk
  // of Interpreter::pickCandidate (the last one when rounding leaves x beyond all).
  b_.SetInsertPoint(rewrite);
  b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), candAlt), chosen);
  llvm::BasicBlock* pick = newBlock("pick");
  b_.CreateCondBr(b_.CreateICmpUGT(n, b_.getInt32(1)), pick, apply);
  b_.SetInsertPoint(pick);
  {
    llvm::Value* x = frameSlots(b_.getDoubleTy(), 1);
    llvm::Value* i = frameSlots(b_.getInt32Ty(), 1);
    b_.CreateStore(b_.CreateFMul(call("fgsg_rt_next", {ctx_}), b_.CreateLoad(b_.getDoubleTy(), total)), x);
    b_.CreateStore(b_.getInt32(0), i);
    b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), b_.CreateInBoundsGEP(b_.getInt32Ty(), candAlt, b_.CreateSub(n, b_.getInt32(1)))), chosen);
    llvm::BasicBlock* loop = newBlock("walk");
    llvm::BasicBlock* test = newBlock("walk_test");
    llvm::BasicBlock* found = newBlock("found");
    llvm::BasicBlock* step = newBlock("walk_next");
    b_.CreateBr(loop);
    b_.SetInsertPoint(loop);
    llvm::Value* iv = b_.CreateLoad(b_.getInt32Ty(), i);
    b_.CreateCondBr(b_.CreateICmpULT(iv, n), test, apply);
    b_.SetInsertPoint(test);
    llvm::Value* w = b_.CreateLoad(b_.getDoubleTy(), b_.CreateInBoundsGEP(b_.getDoubleTy(), candWeight, iv));
    llvm::Value* xv = b_.CreateLoad(b_.getDoubleTy(), x);
    b_.CreateCondBr(b_.CreateFCmpOLT(xv, w), found, step);
    b_.SetInsertPoint(found);
    b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), b_.CreateInBoundsGEP(b_.getInt32Ty(), candAlt, iv)), chosen);
    b_.CreateBr(apply);
    b_.SetInsertPoint(step);
    b_.CreateStore(b_.CreateFSub(xv, w), x);
    b_.CreateStore(b_.CreateAdd(iv, b_.getInt32(1)), i);
    b_.CreateBr(loop);
  }
}

}  // namespace fgsg::backend::codegen::detail
