// CityEngine's CGA as a dialect of fgsg (docs/cga.md, "CGA for CityEngine users"): the
// syntax of `.cga` rule files. Combined grammar for the ANTLR4 C++ target; no actions.
// frontend/cga/ translates this parse tree into the same AST (frontend/ast.h) the .fgsg
// dialect builds, with CityEngine's meaning.
//
// CGA has no statement terminator: a rule's operations end where the next declaration
// begins (a name followed by `-->` or `=`, `attr`, `const`, `@`, ...). ANTLR's adaptive
// prediction sees that `Next -->` cannot continue an operation list.
grammar Cga;

// ================================================================== parser

cgaFile : declaration* EOF ;

declaration
  : versionDecl
  | dialectDecl
  | importDecl
  | styleDecl
  | annotated
  ;

versionDecl : VERSION STRING ;

// `dialect cga;` at the top of a file that is not named .cga.
dialectDecl : DIALECT ID ';'? ;

// `import facade : "facade.cga"` or `import "facade.cga"`, with CityEngine's list of the
// imported file's attrs after the path: `(a, b)` keeps them from this file's attrs of the
// same names, `(a = expr)` sets one, `()` keeps them all; CityEngine's list of the imported
// file's styles after the alias, `import facade (Wide, Tall) : "facade.cga"`, limits which
// of its styles this file gets.
importDecl : IMPORT ( alias=ID ( '(' styles+=ID ( ',' styles+=ID )* ')' )? ':' )? path=STRING
             ( '(' ( importArg ( ',' importArg )* )? ')' )? ;
importArg  : ( key=ID '=' )? expr ;

styleDecl : STYLE name=ID ( EXTENDS base=ID )? ;

annotated : annotation* ( attrDecl | constDecl | functionDecl | ruleDecl ) ;

annotation : AT name=ID ( '(' ( annotationArg ( ',' annotationArg )* )? ')' )? ;
annotationArg : ( key=ID '=' )? expr ;

attrDecl     : ATTR name=ID '=' value ;
constDecl    : CONST name=ID ( '(' params? ')' )? '=' value ;
// `name.attr = value` after `import name : "..."`: the imported file's attr set from here.
functionDecl : name=( ID | QID ) ( '(' params? ')' )? '=' value ;
ruleDecl     : name=ID ( '(' params? ')' )? ARROW ruleBody ;

params : ID ( ',' ID )* ;

// A value: an expression, or CGA's conditional and stochastic forms (nested).
value
  : ( CASE expr ':' value )+ ELSE ':' value       # caseValue
  | ( PERCENT_LIT ':' value )+ ( ELSE ':' value )? # stochasticValue
  | expr                                           # plainValue
  ;

// A rule body: operations, or the same two forms choosing between bodies.
ruleBody
  : ( CASE expr ':' ruleBody )+ ELSE ':' ruleBody       # caseBody
  | ( PERCENT_LIT ':' ruleBody )+ ( ELSE ':' ruleBody )? # stochasticBody
  | operation+                                          # operationBody
  ;

// ---------------------------------------------------------------- operations

operation
  : NIL                                                   # nilOperation
  | name=( ID | QID ) '(' ( expr ( ',' expr )* )? ')' ( splitBody | operationBlock )?  # callOperation
  | leaf=LEAF                                             # leafOperation
  | name=( ID | QID )                                     # shapeOperation
  | '.'                                                   # dotOperation
  | '[' operation* ']'                                    # pushPopOperation
  ;

// `scatter(surface, 20, uniform) { s(1, 4, 1) Tree }`: operations on each new shape, no
// selector. A `{` whose first part reads `key :` or `key =` is a splitBody instead.
operationBlock : '{' operation* '}' ;

// `{ 3 : A | ~1 : B }*` for split, `{ top : A | side = B }` for comp. A part may itself be
// a repeated group: `{ 2 : A | { ~3 : B | 1 : C }* | 2 : D }`.
splitBody : '{' splitPart ( '|' splitPart )* '}' repeat='*'? ;
splitPart
  : key=expr sep=( ':' | '=' ) operation*   # sizedPart
  | splitBody                               # nestedPart
  ;

// ------------------------------------------------------------- expressions

expr
  : primary                                          # primaryExpr
  | op=( '-' | '!' | '+' ) expr                      # unaryExpr
  | expr op=( '*' | '/' | '%' ) expr                 # binaryExpr
  | expr op=( '+' | '-' ) expr                       # binaryExpr
  | expr op=( '<' | '<=' | '>' | '>=' ) expr         # binaryExpr
  | expr op=( '==' | '!=' ) expr                     # binaryExpr
  | expr op='&&' expr                                # binaryExpr
  | expr op='||' expr                                # binaryExpr
  ;

primary
  : number                                           # numberPrimary
  | STRING                                           # stringPrimary
  | flag=( TRUE | FALSE )                            # boolPrimary
  | name=( ID | QID ) '(' ( expr ( ',' expr )* )? ')'  # callPrimary
  | name=( ID | QID )                                # namePrimary
  | '(' expr ')'                                     # parenPrimary
  | '[' ( expr ( ',' expr )* )? ']'                  # arrayPrimary
  | '\'' primary                                     # relativePrimary
  | '~' primary                                      # floatingPrimary
  ;

number : INT | FLOAT ;

// =================================================================== lexer

VERSION  : 'version' ;
DIALECT  : 'dialect' ;
IMPORT   : 'import' ;
STYLE    : 'style' ;
EXTENDS  : 'extends' ;
ATTR     : 'attr' ;
CONST    : 'const' ;
CASE     : 'case' ;
ELSE     : 'else' ;
NIL      : 'NIL' ;
TRUE     : 'true' ;
FALSE    : 'false' ;

ARROW    : '-->' ;
AT       : '@' ;

EQ       : '==' ;
NEQ      : '!=' ;
LE       : '<=' ;
GE       : '>=' ;
LT       : '<' ;
GT       : '>' ;
AND      : '&&' ;
OR       : '||' ;
ASSIGN   : '=' ;
PLUS     : '+' ;
MINUS    : '-' ;
STAR     : '*' ;
SLASH    : '/' ;
PERCENT  : '%' ;
BANG     : '!' ;
PIPE     : '|' ;
QUOTE    : '\'' ;
TILDE    : '~' ;
COLON    : ':' ;
SEMI     : ';' ;
COMMA    : ',' ;
DOT      : '.' ;
LPAREN   : '(' ;
RPAREN   : ')' ;
LBRACK   : '[' ;
RBRACK   : ']' ;
LBRACE   : '{' ;
RBRACE   : '}' ;

// `30%` of a stochastic choice (a space before the '%' reads as the remainder operator).
PERCENT_LIT : ( DIGITS | FLOAT_BODY ) '%' ;
FLOAT    : FLOAT_BODY ;
INT      : DIGITS ;

fragment DIGITS     : [0-9]+ ;
fragment EXPONENT   : [eE] [+-]? DIGITS ;
fragment FLOAT_BODY : DIGITS '.' DIGITS? EXPONENT? | '.' DIGITS EXPONENT? | DIGITS EXPONENT ;
fragment NAME       : [\p{L}_$] [\p{L}\p{N}_$]* ;

// `scope.sx`, `facade.Window`, `material.color.rgb`: one token, written without spaces.
QID      : NAME ( '.' NAME )+ ;
// `Window.`: a leaf shape (no rule is applied), a name and a dot not followed by a name.
LEAF     : NAME '.' ;
ID       : NAME ;

STRING   : '"' ( ~["\\\r\n] | '\\' ~[\r\n] )* '"' ;
UNTERMINATED_STRING : '"' ( ~["\\\r\n] | '\\' ~[\r\n] )* '\\'? ;

LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
HASH_COMMENT  : '#' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
UNTERMINATED_COMMENT : '/*' ( ~'*' | '*'+ ~[*/] )* '*'* EOF ;

WS       : [ \t\r\n\f\u00A0\uFEFF]+ -> skip ;

UNKNOWN_CHAR : . ;
