
// Generated from grammar/Cga.g4 by ANTLR 4.7.2


#include "CgaBaseVisitor.h"


using namespace fgsg_grammar;

