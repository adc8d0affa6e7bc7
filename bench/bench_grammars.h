// The benchmark grammars of bench_derive and bench_jit: derivation throughput on the
// plane (FGSG style), with randomness, with instances, and an L-system.
#pragma once

namespace fgsg::bench {

// A planar pattern in the FGSG style: every A turns and steps twice, 2^depth leaves.
inline const char* kPlanar = R"(
  attr depth = 20;
  Axiom ~> A(0);
  A(n) : n < depth ~> [ Rz(60) T(0.6, 0, 0) A(n + 1) ] [ Rz(-60) T(0.6, 0, 0) A(n + 1) ];
  A(n) ~> Leaf;
)";

// The same pattern placing a cube at every leaf: instances carry 4x4 transforms.
inline const char* kPlanarInstances = R"(
  attr depth = 18;
  Axiom ~> A(0);
  A(n) : n < depth ~> [ Rz(60) T(0.6, 0, 0) A(n + 1) ] [ Rz(-60) T(0.6, 0, 0) A(n + 1) ];
  A(n) ~> S(0.5, 0.5, 0.3) I("cube");
)";

// A stochastic variant: guards, Rand and weighted alternatives on every shape.
inline const char* kStochastic = R"(
  attr depth = 19;
  Axiom ~> A(0);
  A(n) : n < depth ~> [ Rz(Rand(50, 70)) T(Rand(0.5, 0.7), 0, 0) A(n + 1) ]
                      [ Rz(Rand(-70, -50)) T(0.6, 0, 0) A(n + 1) ] : 0.9
                   ~> [ Rz(Rand(-10, 10)) T(0.6, 0, 0) A(n + 1) ] A(n + 1) : 0.1;
  A(n) ~> Leaf;
)";

// ABOP's monopodial tree (Fig. 2.8): a parametric L-system with branches.
inline const char* kLSystem = R"(
  const r1 = 0.9; const r2 = 0.6; const a0 = 45; const a2 = 45; const d = 137.5; const wr = 0.707;
  derive parallel 16;
  axiom: A(1, 0.1);
  A(l, w) -> !(w) F(l) [ &(a0) B(l * r2, w * wr) ] /(d) A(l * r1, w * wr);
  B(l, w) -> !(w) F(l) [ -(a2) C(l * r2, w * wr) ] C(l * r1, w * wr);
  C(l, w) -> !(w) F(l) [ +(a2) B(l * r2, w * wr) ] B(l * r1, w * wr);
)";

}  // namespace fgsg::bench
