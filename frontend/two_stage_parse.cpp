#include "frontend/two_stage_parse.h"

namespace fgsg::frontend {

void makeFirstStage(antlr4::Parser& parser) {
  parser.removeErrorListeners();  // its errors are reported by the second stage
  parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
  parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
}

}  // namespace fgsg::frontend
