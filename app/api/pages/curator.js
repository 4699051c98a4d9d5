// The curator page: browse the library, see pending extensions, write and activate templates.
// Everything comes from the JSON API with the key the curator typed in (kept for the session).
// API text is only ever put into the page as text, never as HTML.
"use strict";

const $ = (id) => document.getElementById(id);
const state = { key: sessionStorage.getItem("safegate-key") || "", current: null, draftId: null };

function el(tag, text, className) {
  const node = document.createElement(tag);
  if (text !== undefined) node.textContent = text;
  if (className) node.className = className;
  return node;
}

async function api(method, path, body) {
  const headers = { "Accept": "application/json" };
  if (state.key) headers["Authorization"] = "Bearer " + state.key;
  if (body !== undefined) headers["Content-Type"] = "application/json";
  const response = await fetch(path, {
    method, headers, body: body === undefined ? undefined : JSON.stringify(body),
  });
  let data = null;
  try { data = await response.json(); } catch (_) { data = null; }
  return { ok: response.ok, status: response.status, data };
}

function problemText(result) {
  const data = result.data || {};
  return `${result.status} ${data.title || "error"}: ${data.detail || ""}`;
}

function showResult(text, className) {
  const box = $("result");
  box.textContent = text;
  box.className = className || "";
}

// --- key ---------------------------------------------------------------------------------
async function useKey(event) {
  if (event) event.preventDefault();
  state.key = $("api-key").value.trim();
  sessionStorage.setItem("safegate-key", state.key);
  if (!state.key) { $("whoami").textContent = "no key"; return refreshAll(); }
  const result = await api("GET", "/keys/me");
  $("whoami").textContent = result.ok
    ? `signed in as ${result.data.role} (${result.data.name})` : problemText(result);
  $("whoami").dataset.role = result.ok ? result.data.role : "";
  await refreshAll();
}

// --- library -----------------------------------------------------------------------------
async function loadTemplates() {
  const params = new URLSearchParams();
  if ($("search").value.trim()) params.set("q", $("search").value.trim());
  if ($("status-filter").value) params.set("status", $("status-filter").value);
  const result = await api("GET", "/templates?" + params.toString());
  const list = $("template-list");
  list.replaceChildren();
  if (!result.ok) { $("template-count").textContent = problemText(result); return; }
  $("template-count").textContent = `${result.data.count} templates`;
  for (const template of result.data.templates) {
    const row = el("tr");
    row.dataset.id = template.id;
    row.append(el("td", template.id), el("td", template.hazard_class),
               el("td", template.status, "status-" + template.status),
               el("td", String(template.version)));
    row.addEventListener("click", () => showTemplate(template.id));
    list.append(row);
  }
}

async function showTemplate(id) {
  const result = await api("GET", "/templates/" + encodeURIComponent(id));
  if (!result.ok) { showResult(problemText(result), "error"); return; }
  const template = result.data;
  state.current = template;
  $("template-detail").hidden = false;
  $("detail-title").textContent = `${template.name} (${template.id})`;
  $("detail-meta").textContent =
    `${template.status} · version ${template.version} of ${template.versions.length}` +
    ` · ${template.category} / ${template.hazard_class} · by ${template.author}`;
  const shown = { ...template };
  delete shown.versions;
  $("detail-body").textContent = JSON.stringify(shown, null, 2);
}

function editable(template) {
  const copy = { ...template };
  for (const key of ["version", "status", "source", "author", "created_at", "versions"]) {
    delete copy[key];
  }
  return copy;
}

async function setStatus(id, action) {
  const result = await api("POST", `/templates/${encodeURIComponent(id)}/${action}`);
  if (!result.ok) { showResult(problemText(result), "error"); return false; }
  showResult(`${id} is now ${result.data.status} (version ${result.data.version})`, "ok");
  await refreshAll();
  return true;
}

// --- pending extensions ------------------------------------------------------------------
async function loadPending() {
  const box = $("pending");
  box.replaceChildren();
  const result = await api("GET", "/extensions/pending");
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
    const start = el("button", "Start a template");
    start.type = "button";
    start.className = "start-template";
    start.addEventListener("click", () => loadEditor(group.suggested_template));
    const redo = el("button", "Re-evaluate waiting requests");
    redo.type = "button";
    redo.className = "reevaluate";
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

// --- editor ------------------------------------------------------------------------------
function loadEditor(template) {
  $("editor").value = JSON.stringify(template, null, 2);
  state.draftId = null;
  $("activate").disabled = true;
  scheduleValidation();
  $("editor").focus();
}

function editorDocument() {
  try { return { document: JSON.parse($("editor").value) }; }
  catch (error) { return { error: "not JSON: " + error.message }; }
}

function renderMessages(errors, warnings) {
  const list = $("messages");
  list.replaceChildren();
  const line = (issue, kind) => {
    const where = issue.line ? ` (line ${issue.line}, column ${issue.column})` : "";
    const item = el("li", `${kind}: ${issue.field}${where}: ${issue.message}`, kind);
    item.dataset.field = issue.field;
    list.append(item);
  };
  errors.forEach((issue) => line(issue, "error"));
  warnings.forEach((issue) => line(issue, "warning"));
}

let validationTimer = null;
let validationRun = 0;
function scheduleValidation() {
  clearTimeout(validationTimer);
  $("validation-status").textContent = "validating…";
  validationTimer = setTimeout(validateNow, 350);
}

async function validateNow() {
  const run = ++validationRun;
  const parsed = editorDocument();
  if (parsed.error) {
    $("validation-status").textContent = "invalid";
    $("validation-status").className = "error";
    renderMessages([{ field: "body", message: parsed.error }], []);
    return;
  }
  const result = await api("POST", "/templates/validate", parsed.document);
  if (run !== validationRun) return;  // a newer edit is being validated
  if (!result.ok) {
    $("validation-status").textContent = problemText(result);
    $("validation-status").className = "error";
    return;
  }
  $("validation-status").textContent = result.data.valid ? "valid" : "invalid";
  $("validation-status").className = result.data.valid ? "ok" : "error";
  renderMessages(result.data.errors, result.data.warnings);
}

async function write(method, path) {
  const parsed = editorDocument();
  if (parsed.error) { showResult(parsed.error, "error"); return; }
  const result = await api(method, path, parsed.document);
  if (!result.ok) {
    showResult(problemText(result), "error");
    if (result.data && result.data.errors) renderMessages(result.data.errors, []);
    return;
  }
  state.draftId = result.data.id;
  $("activate").disabled = result.data.status === "active";
  showResult(`stored ${result.data.id} version ${result.data.version} (${result.data.status})`,
             "ok");
  renderMessages([], result.data.warnings || []);
  await loadTemplates();
}

function createDraft() { return write("POST", "/templates"); }

function saveVersion() {
  const parsed = editorDocument();
  if (parsed.error || !parsed.document.id) { showResult("the template needs an id", "error"); return; }
  return write("PUT", "/templates/" + encodeURIComponent(parsed.document.id));
}

async function activateDraft() {
  if (!state.draftId) return;
  if (await setStatus(state.draftId, "activate")) $("activate").disabled = true;
}

async function refreshAll() { await Promise.all([loadTemplates(), loadPending()]); }

function start() {
  $("api-key").value = state.key;
  $("key-form").addEventListener("submit", useKey);
  let searchTimer = null;
  $("search").addEventListener("input", () => {
    clearTimeout(searchTimer);
    searchTimer = setTimeout(loadTemplates, 250);
  });
  $("status-filter").addEventListener("change", loadTemplates);
  $("editor").addEventListener("input", scheduleValidation);
  $("create").addEventListener("click", createDraft);
  $("save-version").addEventListener("click", saveVersion);
  $("activate").addEventListener("click", activateDraft);
  $("detail-edit").addEventListener("click", () => {
    if (state.current) loadEditor(editable(state.current));
  });
  $("detail-activate").addEventListener("click", () => {
    if (state.current) setStatus(state.current.id, "activate");
  });
  $("detail-deprecate").addEventListener("click", () => {
    if (state.current) setStatus(state.current.id, "deprecate");
  });
  if (state.key) useKey(); else refreshAll();
}

document.addEventListener("DOMContentLoaded", start);
