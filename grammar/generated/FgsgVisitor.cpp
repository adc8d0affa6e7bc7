
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2


#include "FgsgVisitor.h"


using namespace fgsg_grammar;

