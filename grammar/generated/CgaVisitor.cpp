
// Generated from grammar/Cga.g4 by ANTLR 4.7.2


#include "CgaVisitor.h"


using namespace fgsg_grammar;

