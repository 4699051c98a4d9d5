// The curator page's editor bundle (built by `make web` into app/api/pages/vendor/editor.js,
// a single IIFE exposing `window.SafeGateEditor`): a CodeMirror 6 editor for one condition of
// the condition language, with highlighting, completion of the vocabulary and inline
// diagnostics placed from the server's line/column, and a line diff for comparing versions.
// The page never talks to CodeMirror directly, only through the functions exported here.
import { EditorState } from "@codemirror/state";
import {
  EditorView, keymap, lineNumbers, highlightActiveLine, drawSelection, placeholder,
} from "@codemirror/view";
import {
  StreamLanguage, HighlightStyle, syntaxHighlighting, bracketMatching,
} from "@codemirror/language";
import { tags } from "@lezer/highlight";
import { setDiagnostics, lintGutter } from "@codemirror/lint";
import { defaultKeymap, history, historyKeymap } from "@codemirror/commands";
import { autocompletion, completionKeymap } from "@codemirror/autocomplete";
import { diffLines } from "diff";

import { conditionLanguage, KEYWORDS } from "./condition_language.js";

const highlightStyle = HighlightStyle.define([
  { tag: tags.keyword, color: "#7a2fa0", fontWeight: "600" },
  { tag: tags.bool, color: "#7a2fa0" },
  { tag: tags.operator, color: "#a04a00" },
  { tag: tags.special(tags.variableName), color: "#0b62a4", fontWeight: "600" },
  { tag: tags.labelName, color: "#0a7a6a", fontWeight: "600" },
  { tag: tags.function(tags.variableName), color: "#1d5e1d" },
  { tag: tags.typeName, color: "#8a3a3a", fontStyle: "italic" },
  { tag: tags.string, color: "#a3161b" },
  { tag: tags.number, color: "#1a5fb4" },
  { tag: tags.invalid, color: "#ffffff", backgroundColor: "#c01c28" },
]);

const theme = EditorView.theme({
  "&": { fontSize: "0.85rem", border: "1px solid #c3cad2", borderRadius: "4px",
         backgroundColor: "#fff" },
  "&.cm-focused": { outline: "2px solid #7aa7d8" },
  ".cm-content": { fontFamily: "ui-monospace, SFMono-Regular, Menlo, monospace",
                   minHeight: "2.2em" },
  ".cm-gutters": { backgroundColor: "#f3f5f7", borderRight: "1px solid #e1e5ea" },
});

function completions(symbols) {
  const options = [
    ...KEYWORDS.map((word) => ({ label: word, type: "keyword" })),
    ...symbols.map((symbol) => ({
      label: symbol.name, type: "function",
      detail: `(${symbol.args.join(", ")}) -> ${symbol.result}`, info: symbol.meaning,
    })),
  ];
  return (context) => {
    const word = context.matchBefore(/[$@]?[A-Za-z_][A-Za-z0-9_]*/);
    if (!word || (word.from === word.to && !context.explicit)) return null;
    if (/^[$@]/.test(word.text)) return null;  // variables are the template's own
    return { from: word.from, options, validFor: /^[A-Za-z0-9_]*$/ };
  };
}

/**
 * A condition editor in `parent`.
 * @param {HTMLElement} parent where the editor goes
 * @param {{doc?: string, symbols?: object[], onChange?: (text: string) => void,
 *          label?: string}} options the formula, the vocabulary (GET /vocabulary's symbols)
 *   for highlighting known names and completing them, a callback on every edit, an aria label
 * @returns {EditorView}
 */
export function formulaEditor(parent, options = {}) {
  const symbols = options.symbols || [];
  const known = new Set(symbols.map((symbol) => symbol.name));
  const extensions = [
    lineNumbers(), history(), drawSelection(), highlightActiveLine(), bracketMatching(),
    EditorView.lineWrapping, lintGutter(), theme,
    StreamLanguage.define(conditionLanguage(known)), syntaxHighlighting(highlightStyle),
    autocompletion({ override: [completions(symbols)] }),
    keymap.of([...defaultKeymap, ...historyKeymap, ...completionKeymap]),
    placeholder("e.g. @object != $obj or not hot($obj)"),
    EditorView.contentAttributes.of({ "aria-label": options.label || "condition" }),
    EditorView.updateListener.of((update) => {
      if (update.docChanged && options.onChange) options.onChange(update.state.doc.toString());
    }),
  ];
  return new EditorView({
    parent, state: EditorState.create({ doc: options.doc || "", extensions }),
  });
}

/** The editor's text. */
export function textOf(view) {
  return view.state.doc.toString();
}

/** Replace the editor's text (as one undoable edit). */
export function setText(view, text) {
  view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } });
}

// A position from the server (1-based line and column) as a range in the document: the word
// or symbol starting there, or the whole text when the issue has no position.
function rangeOf(doc, issue) {
  if (!issue.line || issue.line > doc.lines) return { from: 0, to: doc.length };
  const line = doc.line(issue.line);
  const from = Math.min(line.from + Math.max((issue.column || 1) - 1, 0), line.to);
  const rest = line.text.slice(from - line.from);
  const word = /^[$@]?[A-Za-z0-9_]+/.exec(rest);
  return { from, to: from + (word ? word[0].length : Math.min(1, rest.length)) };
}

/**
 * Show issues inline (underline and gutter mark); an empty list clears them.
 * @param {EditorView} view
 * @param {{message: string, line?: number, column?: number, severity?: string}[]} issues
 */
export function showIssues(view, issues) {
  const doc = view.state.doc;
  const diagnostics = issues.map((issue) => ({
    ...rangeOf(doc, issue), severity: issue.severity || "error", message: issue.message,
  }));
  view.dispatch(setDiagnostics(view.state, diagnostics));
}

/**
 * A line diff of two texts: parts in order, each `{kind: "same"|"added"|"removed", lines}`.
 */
export function lineDiff(before, after) {
  return diffLines(before, after).map((part) => ({
    kind: part.added ? "added" : part.removed ? "removed" : "same",
    lines: part.value.replace(/\n$/, "").split("\n"),
  }));
}
