// The curator page: browse the library, see pending extensions, write and activate templates.
// Everything comes from the JSON API with the key the curator typed in (kept for the session).
// This module wires the parts together: the table (library.js), a template's versions and
// their diff (versions.js), the form and its condition editors (template_form.js), live
// validation, writes and the pending extensions.
import { $, api, el, problemText, showResult, session, debounced } from "./api.js";
import { loadTemplates, setupLibrary } from "./library.js";
import { editable, setupVersions, showVersions } from "./versions.js";
import { fillForm, readForm, setChoices, setupForm, showFormIssues } from "./template_form.js";

const page = { current: null, draftId: null, validationRun: 0 };

// --- key ---------------------------------------------------------------------------------
async function useKey(event) {
  if (event) event.preventDefault();
  session.key = $("api-key").value.trim();
  sessionStorage.setItem("safegate-key", session.key);
  if (!session.key) { $("whoami").textContent = "no key"; return refreshAll(); }
  const result = await api("GET", "/keys/me");
  // Lists first, then the name: once "signed in" shows, what is on the page is the key's view.
  await Promise.all([refreshAll(), formChoices().then(setChoices)]);
  $("whoami").textContent = result.ok
    ? `signed in as ${result.data.role} (${result.data.name})` : problemText(result);
  $("whoami").dataset.role = result.ok ? result.data.role : "";
}

// --- one template ------------------------------------------------------------------------
async function showTemplate(id) {
  const result = await api("GET", "/templates/" + encodeURIComponent(id));
  if (!result.ok) { showResult(problemText(result), "error"); return; }
  const template = result.data;
  page.current = template;
  $("template-detail").hidden = false;
  $("detail-title").textContent = `${template.name} (${template.id})`;
  $("detail-meta").textContent =
    `${template.status} · version ${template.version} of ${template.versions.length}` +
    ` · ${template.category} / ${template.hazard_class} · by ${template.author}`;
  const shown = { ...template };
  delete shown.versions;
  $("detail-body").textContent = JSON.stringify(shown, null, 2);
  showVersions(template);
  for (const row of document.querySelectorAll("#template-list tr")) {
    row.classList.toggle("selected", row.dataset.id === id);
  }
}

async function setStatus(id, action) {
  const result = await api("POST", `/templates/${encodeURIComponent(id)}/${action}`);
  if (!result.ok) { showResult(problemText(result), "error"); return false; }
  showResult(`${id} is now ${result.data.status} (version ${result.data.version})`, "ok");
  await refreshAll();
  if (page.current && page.current.id === id) await showTemplate(id);
  return true;
}

// --- pending extensions ------------------------------------------------------------------
async function loadPending() {
  const box = $("pending");
  const result = await api("GET", "/extensions/pending");
  box.replaceChildren();
  if (!result.ok) { box.append(el("p", problemText(result), "error")); return; }
  if (!result.data.classes.length) { box.append(el("p", "Nothing is waiting.", "muted")); }
  for (const group of result.data.classes) {
    const div = el("div", undefined, "group");
    div.dataset.hazardClass = group.hazard_class;
    const covered = group.covered ? `covered by ${group.covered_by.join(", ")}` : "not covered";
    div.append(el("strong", group.hazard_class),
               el("span", ` · ${group.count} waiting · ${covered}`, "muted"));
    const list = el("ul");
    for (const request of group.requests) list.append(el("li", request.command));
    div.append(list);
    const start = el("button", "Start a template", "start-template");
    start.type = "button";
    start.addEventListener("click", () => loadEditor(group.suggested_template));
    const redo = el("button", "Re-evaluate waiting requests", "reevaluate");
    redo.type = "button";
    redo.disabled = !group.covered;
    redo.addEventListener("click", () => reevaluate(group.hazard_class));
    div.append(start, redo);
    box.append(div);
  }
}

async function reevaluate(hazardClass) {
  const result = await api("POST", "/extensions/reevaluate", { hazard_class: hazardClass });
  if (!result.ok) { showResult(problemText(result), "error"); return; }
  const decisions = result.data.results.map((r) => `${r.decision.decision} (${r.decision.rule})`);
  showResult(`re-evaluated ${result.data.count}: ${decisions.join(", ")}`, "ok");
  await loadPending();
}

// --- editor and validation ---------------------------------------------------------------
function loadEditor(template) {
  fillForm(template);
  page.draftId = null;
  $("activate").disabled = true;
  validateSoon();
  $("editor-section").scrollIntoView({ block: "start" });
}

function renderMessages(errors, warnings) {
  const issues = [...errors.map((issue) => ({ ...issue, kind: "error" })),
                  ...warnings.map((issue) => ({ ...issue, kind: "warning" }))];
  $("messages").replaceChildren(...issues.map((issue) => {
    const where = issue.line ? ` (line ${issue.line}, column ${issue.column})` : "";
    const item = el("li", `${issue.kind}: ${issue.field}${where}: ${issue.message}`, issue.kind);
    item.dataset.field = issue.field;
    return item;
  }));
  showFormIssues(issues);
}

function setValidationStatus(text, className) {
  $("validation-status").textContent = text;
  $("validation-status").className = className;
}

async function validateNow() {
  const run = ++page.validationRun;
  const document = readForm();
  $("document-preview").textContent = JSON.stringify(document, null, 2);
  const result = await api("POST", "/templates/validate", document);
  if (run !== page.validationRun) return;  // a newer edit is being validated
  if (!result.ok) { setValidationStatus(problemText(result), "error"); return; }
  setValidationStatus(result.data.valid ? "valid" : "invalid",
                      result.data.valid ? "ok" : "error");
  renderMessages(result.data.errors, result.data.warnings);
}

const validateLater = debounced(validateNow, 350);
function validateSoon() {
  page.validationRun++;  // an answer to an older request is stale from now on
  setValidationStatus("validating…", "muted");
  validateLater();
}

async function write(method, path) {
  const result = await api(method, path, readForm());
  if (!result.ok) {
    showResult(problemText(result), "error");
    if (result.data && result.data.errors) renderMessages(result.data.errors, []);
    return;
  }
  page.draftId = result.data.id;
  $("activate").disabled = result.data.status === "active";
  showResult(`stored ${result.data.id} version ${result.data.version} (${result.data.status})`,
             "ok");
  renderMessages([], result.data.warnings || []);
  await loadTemplates();
  // A new version of the template on show: its diff now offers that version.
  if (page.current && page.current.id === result.data.id) await showTemplate(result.data.id);
}

function saveVersion() {
  const id = readForm().id;
  if (!id) { showResult("the template needs an id", "error"); return; }
  return write("PUT", "/templates/" + encodeURIComponent(id));
}

async function activateDraft() {
  if (!page.draftId) return;
  if (await setStatus(page.draftId, "activate")) $("activate").disabled = true;
}

async function refreshAll() { await Promise.all([loadTemplates(), loadPending()]); }

// What the form offers to choose from: the vocabulary's symbols and actions, the library's
// hazard classes. A failure leaves the lists empty; typing still works.
async function formChoices() {
  const [vocabulary, library] = await Promise.all([
    api("GET", "/vocabulary"), api("GET", "/templates")]);
  const classes = library.ok
    ? [...new Set(library.data.templates.map((t) => t.hazard_class))].sort() : [];
  return {
    symbols: vocabulary.ok ? vocabulary.data.symbols : [],
    actions: vocabulary.ok ? vocabulary.data.actions.map((action) => action.name) : [],
    hazardClasses: classes,
  };
}

async function start() {
  $("api-key").value = session.key;
  $("key-form").addEventListener("submit", useKey);
  setupLibrary(showTemplate);
  setupVersions();
  setupForm(validateSoon);
  $("create").addEventListener("click", () => write("POST", "/templates"));
  $("save-version").addEventListener("click", saveVersion);
  $("activate").addEventListener("click", activateDraft);
  $("detail-edit").addEventListener("click", () => {
    if (page.current) loadEditor(editable(page.current));
  });
  $("detail-activate").addEventListener("click", () => {
    if (page.current) setStatus(page.current.id, "activate");
  });
  $("detail-deprecate").addEventListener("click", () => {
    if (page.current) setStatus(page.current.id, "deprecate");
  });
  if (session.key) await useKey();
  else await Promise.all([refreshAll(), formChoices().then(setChoices)]);
  document.body.dataset.ready = "true";  // for tests and scripts: the page is wired
}

start();
