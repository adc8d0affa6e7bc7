// The .fgsg language: CGA shape grammars, L-systems and field-guided shape grammars in
// one syntax (see docs/language.md). Combined grammar for the ANTLR4 C++ target; no
// actions. The AST is built from this parse tree by frontend/ast_builder.cpp.
//
// Two things are decided outside this file, in the front end:
//  * The ';' after a rule may be left out at the end of a line: the lexing step
//    (frontend/lex.cpp) inserts an implicit ';' before a line that begins a new rule or
//    declaration, and at the end of the file. So `A ~> B ~> C` on one line stays one rule
//    with two branches, while `start = S F` <newline> `F = [ ... ]` is two rules. Here
//    every statement ends in ';', which keeps error messages and recovery precise.
//  * Statements are parsed one at a time (rule `statement`, frontend/parse.cpp), so a
//    syntax error skips to the end of its statement and parsing resumes with the next.
grammar Fgsg;

// A '.' that is no member access (`Scope.sx`: a name, '.', a name, written together) is
// an ABOP polygon vertex, and a ';' with more of a rule's successor after it on its line
// is lpfg's colour step (ABOP's '); the lexing step retypes them (frontend/lex.cpp).
tokens { VERTEX, COLORSTEP }

// ================================================================== parser

program : statement* EOF ;

statement
  : importDecl
  | valueDecl
  | surfaceDecl
  | fieldDecl
  | textureDecl
  | tilesetDecl
  | deriveDecl
  | turtleDecl
  | ignoreDecl
  | collisionDecl
  | axiomDecl
  | priorityDecl
  | grammarRule
  | ';'
  ;

// ------------------------------------------------------------ declarations

valueDecl   : kind=(CONST | ATTR) name=ID '=' expr ';' ;

// `import "std/cga/facade" as facade (floor_height = 3.5);`: a module's rules and
// declarations (frontend/imports.cpp); `as` is a plain name here, so it stays usable.
// `facade.Window` is one name: the lexing step joins an alias, '.' and a name.
importDecl  : IMPORT path=STRING ( asWord=ID alias=ID )? ( '(' importSetting ( ',' importSetting )* ')' )? ';' ;
importSetting : name=ID '=' expr ;

surfaceDecl : SURFACE ( path=STRING | generator=ID callArgs? ) ';' ;

fieldDecl   : FIELD name=ID '=' fieldSource ';' ;

// `design` is a word, not a keyword; the builder checks it.
fieldSource
  : designWord=ID function=ID '{' fieldDesignItem* '}'
  | function=ID callArgs?
  ;

// `wedge at (0.2,0.1,0.9) decay 2;`: a kind, then keywords with optional values.
fieldDesignItem : kind=ID fieldDesignWord* ';' ;

fieldDesignWord
  : keyword=ID designValue?
  | designValue
  ;

// No bare identifiers here: an identifier after a keyword is the next keyword.
designValue
  : sign=('-' | '+')? ( number | STRING | TRUE | FALSE | '(' expr (',' expr)* ')' )
  ;

textureDecl : TEXTURE name=ID '=' path=STRING ';' ;

// `tileset ornament { locus arc = cubic((0.5,0), ...); section round = polyline(...);
// orientations 0, 90; symbols "AB"; }`: tiles for Evolve (Chan & Hui). An item is a kind,
// an optional `name =`, then values; the front end checks which kinds take which values.
tilesetDecl : TILESET name=ID '{' tilesetItem* '}' ';' ;
tilesetItem : kind=ID ( itemName=ID '=' )? expr ( ',' expr )* ';' ;

deriveDecl  : DERIVE order=ID steps=expr? ';' ;

turtleDecl  : TURTLE turtleSetting* ';' ;
turtleSetting : name=ID value=expr ;

// ABOP's `#ignore: + - F;`: symbols that context matching steps over.
ignoreDecl  : IGNORE ':'? ignoredSymbol+ ';' ;
ignoredSymbol : ID | turtleSymbol ;

// `collision all centre 0.25;`: words and radii in any order; the front end checks them
// (a radius follows `centre` / `geodesic`; a '-' is accepted so that a negative radius
// gets a clear message instead of a syntax error).
collisionDecl : COLLISION collisionWord* ';' ;
collisionWord : word=ID | sign='-'? number ;

axiomDecl   : AXIOM ':' successor ';' ;

priorityDecl : PRIORITY sign='-'? level=INT ':' ;

// ------------------------------------------------------------------- rules

// `X : Y ~> Z` is ambiguous (label X, predecessor Y / predecessor X, guard Y). ANTLR
// resolves a true ambiguity to the first alternative, which for `( )?` is "present":
// whenever the text after the first colon is a valid rule head, X is the label.
grammarRule
  : ( label=ruleLabel ':' )? ruleHead ( ':' guard=expr )? arrow ruleBody ';'
  ;

ruleLabel : INT | ID ;

ruleHead : ( leftContext '<' )? predecessor=modulePattern ( '>' rightContext )? ;

leftContext  : modulePattern+ ;
rightContext : contextModule+ ;
contextModule : modulePattern | open='[' | close=']' ;

// A turtle symbol may be rewritten too (ABOP's `+ -> -`, rules for `!(w)`).
modulePattern : ( name=ID | turtle=turtleSymbol ) ( '(' ( paramDecl ( ',' paramDecl )* )? ')' )? ;
turtleSymbol : '+' | '-' | '&' | '^' | '\\' | '/' | '|' | '!' ;
paramDecl : ID ;

// Müller's guarded form `pred ~> guard ~> succ : p ~> succ : p`: the part after the
// first arrow is a guard only when it is not a successor. Listing the plain form first
// makes `A ~> B ~> C` (where B is both) two branches.
ruleBody
  : branch ( arrow branch )*
  | mullerGuard=expr arrow branch ( arrow branch )*
  ;

branch : successor ( ':' probability=expr )? ;

arrow : ARROW | '=' ;

// -------------------------------------------------------------- successors

successor : EPSILON | sequenceItem+ ;

// At sequence level '|' is a turtle symbol; inside `{ }` it separates body parts.
// COLORSTEP is lpfg's `;` inside a successor (ABOP's ').
// ABOP's polygons: `{` starts one, `.` (an item) records the turtle's position as a
// vertex, `}` fills it. They need not nest with brackets (the cordate leaf
// `[+A{.].C.}`), so `{` and `}` are items of their own, at sequence level only: inside a
// body they would be read as the body's braces. A name directly followed by `{ ... }`
// parses as a body; the front end reads it as a polygon when the name takes none and it
// has a `.` (frontend/ast_builder.cpp). ABOP's `~leaf(s)` places a predefined surface.
sequenceItem
  : item
  | symbol=( '|' | '||' | COLORSTEP ) callArgs?
  | polygon=( '{' | '}' )
  ;

item
  : name=ID callArgs? body?                                                   # callItem
  | symbol=( '+' | '-' | '&' | '&&' | '^' | '\\' | '/' | '!' | '$' | '%' | '\'' ) callArgs? # turtleItem
  | '[' sequenceItem* ']'                                                     # bracketItem
  | polygon=VERTEX                                                            # polygonItem
  | '~' ( surface=ID | surfaceFile=STRING ) callArgs?                          # surfaceItem
  ;

callArgs : '(' ( expr ( ',' expr )* )? ')' ;

// CGA's repeat split: `Subdiv("X"){ ~1: Wall | 1.4: Window }*` repeats the parts.
body : '{' bodyPart ( ( '|' | ',' ) bodyPart )* '}' repeat='*'? ;

// A part may name the components it takes, `Comp("f"){ front: A | side: B }`, merged into
// one shape with `=:` (CGA's `=`: `Comp("e"){ all=: A }`, `Setback(2){ all=: A }`), or give
// its size, CGA's split syntax `Subdiv("Y"){ 4: Ground | ~3: Floor }`.
bodyPart : ( selector=ID merged='='? ':' | size=expr ':' )? ( EPSILON | item+ ) ;

// ------------------------------------------------------------- expressions

// Precedence from high to low: postfix (in primary), '^' (right), unary, * / %, + -,
// comparisons, equality, &&, ||, ?: (right).
expr
  : primary                                         # primaryExpr
  | <assoc=right> expr op='^' expr                  # binaryExpr
  | op=( '-' | '!' | '+' ) expr                     # unaryExpr
  | expr op=( '*' | '/' | '%' ) expr                # binaryExpr
  | expr op=( '+' | '-' ) expr                      # binaryExpr
  | expr op=( '<' | '<=' | '>' | '>=' ) expr        # binaryExpr
  | expr op=( '==' | '!=' ) expr                    # binaryExpr
  | expr op='&&' expr                               # binaryExpr
  | expr op='||' expr                               # binaryExpr
  | <assoc=right> expr '?' expr ':' expr            # ternaryExpr
  ;

primary
  : number                                          # numberPrimary
  | RELSIZE                                         # relSizePrimary
  | STRING                                          # stringPrimary
  | value=( TRUE | FALSE )                          # boolPrimary
  | object=ID '.' member=ID ( '.' sub=ID )? callArgs?  # memberPrimary
  | name=ID callArgs                                # callPrimary
  | name=ID                                         # identPrimary
  | '(' expr ')'                                    # parenPrimary
  | '(' expr ( ',' expr )+ ')'                      # vectorPrimary
  | '~' primary                                     # floatSizePrimary
  ;

number : INT | FLOAT ;

// =================================================================== lexer

IMPORT   : 'import' ;
CONST    : 'const' ;
ATTR     : 'attr' ;
SURFACE  : 'surface' ;
FIELD    : 'field' ;
TEXTURE  : 'texture' ;
TILESET  : 'tileset' ;
DERIVE   : 'derive' ;
TURTLE   : 'turtle' ;
IGNORE   : '#ignore' ;
COLLISION: 'collision' ;
AXIOM    : 'axiom' ;
PRIORITY : 'priority' | 'PRIORITY' ;
TRUE     : 'true' ;
FALSE    : 'false' ;
EPSILON  : '\u03B5' | 'epsilon' | 'NIL' ;  // ε

ARROW    : '~>' | '->' | '\u2192' | '\u21DD' ;  // → ⇝  ('=' is ASSIGN, also an arrow)

ASSIGN   : '=' ;
EQ       : '==' ;
NEQ      : '!=' ;
LE       : '<=' ;
GE       : '>=' ;
LT       : '<' ;
GT       : '>' ;
AND      : '&&' ;
OR       : '||' ;
PLUS     : '+' ;
MINUS    : '-' ;
STAR     : '*' ;
SLASH    : '/' ;
PERCENT  : '%' ;
CARET    : '^' ;
BANG     : '!' ;
AMP      : '&' ;
PIPE     : '|' ;
BACKSLASH: '\\' ;
DOLLAR   : '$' ;
QUOTE    : '\'' ;
TILDE    : '~' ;
QUESTION : '?' ;
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

// A number immediately followed by 'r' is a relative size (CGA): 1r, 0.5r.
RELSIZE  : ( DIGITS | FLOAT_BODY ) 'r' ;
FLOAT    : FLOAT_BODY ;
INT      : DIGITS ;

fragment DIGITS     : [0-9]+ ;
fragment EXPONENT   : [eE] [+-]? DIGITS ;
fragment FLOAT_BODY : DIGITS '.' DIGITS? EXPONENT? | '.' DIGITS EXPONENT? | DIGITS EXPONENT ;

ID       : [\p{L}_] [\p{L}\p{N}_]* ;

STRING   : '"' ( ~["\\\r\n] | '\\' ~[\r\n] )* '"' ;
// Reported as E001 by the front end, which then reads it as a string up to the line end.
UNTERMINATED_STRING : '"' ( ~["\\\r\n] | '\\' ~[\r\n] )* '\\'? ;

LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
// Cannot contain "*/", so it only wins when the comment runs to the end of the file.
UNTERMINATED_COMMENT : '/*' ( ~'*' | '*'+ ~[*/] )* '*'* EOF ;

WS       : [ \t\r\n\f\u00A0\uFEFF]+ -> skip ;

// Anything else: one token per character, reported as E001 by the front end (merging
// runs), so the lexer itself never reports an error.
UNKNOWN_CHAR : . ;
