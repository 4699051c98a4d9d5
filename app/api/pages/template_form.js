// The template form: a template's fields, its variables as rows and its conditions as cards,
// each condition's formula in a CodeMirror editor (the vendored bundle, window.SafeGateEditor).
// It reads back into the JSON document the API takes and places validation issues where they
// belong: beside the field they name, or inside the formula at the line and column the server
// gave. Every control carries the API's dotted field path in `data-field`
// (`body.guards.0.formula`), so an issue finds its place by its `field`.
import { $, el } from "./api.js";

const FIELDS = ["id", "name", "category", "hazard_class", "severity", "preventability",
                "analysis", "applies", "description", "iso_clause"];
const FIELD_DEFAULTS = { category: "physical", severity: "moderate",
                         preventability: "preventable", analysis: "simulate",
                         applies: "matched" };
const KINDS = { invariant: "invariants", guard: "guards", abort: "aborts" };
const VARIABLE_TYPES = ["object", "person", "room", "robot", "entity", "number", "string",
                        "bool"];

const form = { symbols: [], changed: () => {}, conditions: [] };

function input(className, value, placeholder) {
  const node = el("input", undefined, className);
  node.value = value ?? "";
  if (placeholder) node.placeholder = placeholder;
  return node;
}

function removeButton(what, onRemove) {
  const button = el("button", "×", "remove");
  button.type = "button";
  button.title = `remove this ${what}`;
  button.addEventListener("click", () => { onRemove(); form.changed(); });
  return button;
}

// --- variables ---------------------------------------------------------------------------
function variableRow(variable = {}) {
  const row = el("tr", undefined, "variable");
  const type = el("select", undefined, "variable-type");
  for (const name of VARIABLE_TYPES) type.append(el("option", name));
  type.value = variable.type || "object";
  const shownDefault = variable.default === undefined || variable.default === null
    ? "" : typeof variable.default === "string" ? variable.default
    : JSON.stringify(variable.default);
  const cellsOf = [
    input("variable-name", variable.name, "obj"), type,
    input("variable-default", shownDefault, "none"),
    input("variable-description", variable.description, "what it stands for"),
  ];
  for (const control of cellsOf) { const cell = el("td"); cell.append(control); row.append(cell); }
  const last = el("td");
  last.append(removeButton("variable", () => row.remove()));
  row.append(last);
  $("variable-rows").append(row);
}

// A default as typed: empty is none; a number, true/false or JSON literal as such; else text.
function parseDefault(text, type) {
  const trimmed = text.trim();
  if (!trimmed) return undefined;
  if (type === "string") return text;
  try { return JSON.parse(trimmed); } catch (_) { return text; }
}

function readVariables() {
  return [...$("variable-rows").querySelectorAll("tr.variable")].map((row, index) => {
    const get = (cls) => row.querySelector("." + cls);
    for (const [cls, key] of [["variable-name", "name"], ["variable-type", "type"],
      ["variable-default", "default"], ["variable-description", "description"]]) {
      get(cls).dataset.field = `body.variables.${index}.${key}`;
    }
    row.dataset.field = `body.variables.${index}`;
    const variable = { name: get("variable-name").value.trim(),
                       type: get("variable-type").value };
    const value = parseDefault(get("variable-default").value, variable.type);
    if (value !== undefined) variable.default = value;
    const description = get("variable-description").value.trim();
    if (description) variable.description = description;
    return variable;
  });
}

// --- conditions --------------------------------------------------------------------------
function conditionCard(kind, condition = {}) {
  const card = el("div", undefined, "condition");
  const kindSelect = el("select", undefined, "condition-kind");
  kindSelect.setAttribute("aria-label", "kind");
  for (const name of Object.keys(KINDS)) kindSelect.append(el("option", name));
  kindSelect.value = kind;
  const id = input("condition-id", condition.id, "condition_id");
  const action = input("condition-action", condition.action, "guarded action, e.g. HandOver");
  action.setAttribute("list", "action-names");
  const head = el("div", undefined, "condition-head");
  const entry = { card, kindSelect, id, action, description: null, editor: null, holder: null };
  head.append(kindSelect, id, action, removeButton("condition", () => {
    card.remove();
    form.conditions = form.conditions.filter((other) => other !== entry);
  }));
  const holder = el("div", undefined, "formula-editor");
  const description = input("condition-description", condition.description,
                            "what it prevents, in plain words");
  const showAction = () => { action.hidden = kindSelect.value !== "guard"; };
  kindSelect.addEventListener("change", showAction);
  showAction();
  card.append(head, holder, el("div", undefined, "condition-issues"), description);
  $("condition-list").append(card);
  entry.description = description;
  entry.holder = holder;
  entry.editor = window.SafeGateEditor.formulaEditor(holder, {
    doc: condition.formula || "", symbols: form.symbols, label: "formula",
    onChange: () => form.changed(),
  });
  form.conditions.push(entry);
  return entry;
}

function readConditions(document) {
  const counts = { invariant: 0, guard: 0, abort: 0 };
  for (const kind of Object.keys(KINDS)) document[KINDS[kind]] = [];
  for (const entry of form.conditions) {
    const kind = entry.kindSelect.value;
    const path = `body.${KINDS[kind]}.${counts[kind]++}`;
    entry.card.dataset.field = path;
    entry.id.dataset.field = path + ".id";
    entry.action.dataset.field = path + ".action";
    entry.description.dataset.field = path + ".description";
    entry.holder.dataset.field = path + ".formula";
    const condition = { id: entry.id.value.trim(),
                        formula: window.SafeGateEditor.textOf(entry.editor),
                        description: entry.description.value.trim() };
    if (kind === "guard") condition.action = entry.action.value.trim();
    document[KINDS[kind]].push(condition);
  }
}

// --- the whole form ----------------------------------------------------------------------
/** Fill the form with a template document (missing fields get their defaults). */
export function fillForm(template) {
  const fields = $("template-form").elements;
  for (const name of FIELDS) fields[name].value = template[name] ?? FIELD_DEFAULTS[name] ?? "";
  $("variable-rows").replaceChildren();
  for (const variable of template.variables || []) variableRow(variable);
  for (const entry of form.conditions) entry.editor.destroy();
  form.conditions = [];
  $("condition-list").replaceChildren();
  for (const [kind, key] of Object.entries(KINDS)) {
    for (const condition of template[key] || []) conditionCard(kind, condition);
  }
  showFormIssues([]);
}

/** The form as the JSON document POST /templates takes. */
export function readForm() {
  const fields = $("template-form").elements;
  const document = {};
  for (const name of FIELDS) document[name] = fields[name].value.trim();
  document.variables = readVariables();
  readConditions(document);
  return document;
}

function fieldElement(field) {
  // The issue's own field, or the nearest enclosing one on the page (`body.guards.0.x` -> the
  // card of `body.guards.0`).
  const parts = field.split(".");
  for (let end = parts.length; end > 1; end--) {
    const found = $("template-form").querySelector(
      `[data-field="${CSS.escape(parts.slice(0, end).join("."))}"]`);
    if (found) return found;
  }
  return null;
}

/** Place issues (`{field, message, line?, column?}`, `kind` error|warning) inline; [] clears. */
export function showFormIssues(issues) {
  for (const old of document.querySelectorAll("#template-form .field-issue")) old.remove();
  for (const marked of document.querySelectorAll("#template-form .invalid")) {
    marked.classList.remove("invalid");
  }
  const byEditor = new Map(form.conditions.map((entry) => [entry, []]));
  for (const issue of issues) {
    const target = fieldElement(issue.field);
    if (!target) continue;
    const entry = form.conditions.find((c) => c.holder === target);
    if (entry) {
      byEditor.get(entry).push({ ...issue, severity: issue.kind });
      const position = `line ${issue.line}, column ${issue.column}`;
      const where = issue.line && !issue.message.includes(position) ? position + ": " : "";
      entry.card.querySelector(".condition-issues")
        .append(el("div", where + issue.message, `field-issue ${issue.kind}`));
      continue;
    }
    target.classList.add("invalid");
    const note = el("span", issue.message, `field-issue ${issue.kind}`);
    const anchor = target.closest("label, td, .condition-head") || target;
    anchor.append(note);
  }
  for (const [entry, found] of byEditor) window.SafeGateEditor.showIssues(entry.editor, found);
}

/** What the form offers: the vocabulary's symbols (for editors made from now on), action
 * names and hazard classes. */
export function setChoices({ symbols, actions, hazardClasses }) {
  form.symbols = symbols;
  $("action-names").replaceChildren(...actions.map((name) => {
    const option = el("option"); option.value = name; return option;
  }));
  $("hazard-classes").replaceChildren(...hazardClasses.map((name) => {
    const option = el("option"); option.value = name; return option;
  }));
}

/** Wire the form: `onChange` is called after every edit. */
export function setupForm(onChange) {
  form.changed = onChange;
  $("template-form").addEventListener("input", onChange);
  $("template-form").addEventListener("change", onChange);
  $("add-variable").addEventListener("click", () => { variableRow(); onChange(); });
  for (const button of document.querySelectorAll(".add-condition")) {
    button.addEventListener("click", () => {
      const entry = conditionCard(button.dataset.kind);
      entry.id.focus();
      onChange();
    });
  }
}
