// The condition language (templates_db/README.md, "The condition language") as a CodeMirror
// stream tokenizer: keywords, connectives and comparisons, `$variables`, `@object`/`@target`,
// the vocabulary's predicates and functions, quantifier types, strings and numbers. It only
// colours text; the server's parser is the one that decides what is valid.

export const KEYWORDS = ["not", "and", "or", "forall", "exists", "true", "false"];
const TYPES = new Set(["person", "object", "room"]);
const OPERATORS = /^(<->|->|==|!=|<=|>=|[<>+\-*/.:,])/;

/** A StreamLanguage spec; names in `known` (the vocabulary) are coloured as functions. */
export function conditionLanguage(known) {
  return {
    name: "safegate-condition",
    startState: () => ({ afterColon: false }),
    token(stream, state) {
      if (stream.eatSpace()) return null;
      if (stream.match(/^"(?:[^"\\]|\\.)*"?/)) return "string";
      if (stream.match(/^\d+(?:\.\d+)?/)) return "number";
      if (stream.match(/^\$[A-Za-z_][A-Za-z0-9_]*/)) return "variableName.special";
      if (stream.match(/^@[A-Za-z_][A-Za-z0-9_]*/)) return "labelName";
      const word = stream.match(/^[A-Za-z_][A-Za-z0-9_]*/);
      if (word) {
        const text = word[0];
        const wasTyped = state.afterColon;
        state.afterColon = false;
        if (text === "true" || text === "false") return "bool";
        if (KEYWORDS.includes(text)) return "keyword";
        if (wasTyped && TYPES.has(text)) return "typeName";
        if (known.has(text)) return "variableName.function";
        return "variableName";
      }
      if (stream.match(OPERATORS)) {
        state.afterColon = stream.current() === ":";
        return "operator";
      }
      if (stream.match(/^[()]/)) return "paren";
      stream.next();
      return "invalid";
    },
    languageData: { commentTokens: {} },
  };
}
