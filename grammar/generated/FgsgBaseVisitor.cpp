
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2


#include "FgsgBaseVisitor.h"


using namespace fgsg_grammar;

