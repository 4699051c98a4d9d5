// One template in detail: its metadata, its actions and a line diff between two of its versions
// (GET /templates/{id} answers every stored version). A version is compared as the JSON of
// what a curator writes: the bookkeeping that differs between any two versions (number,
// status, author, time) is left out of the text and shown in the summary instead.
import { $, el } from "./api.js";

const BOOKKEEPING = ["version", "status", "source", "author", "created_at", "versions"];
let versions = [];

/** A template without its bookkeeping fields: what the editor edits and the diff compares. */
export function editable(template) {
  const copy = { ...template };
  for (const key of BOOKKEEPING) delete copy[key];
  return copy;
}

function versionLabel(record) {
  const when = record.created_at ? record.created_at.slice(0, 16).replace("T", " ") : "";
  return `v${record.version} · ${record.status} · ${record.author} ${when}`.trim();
}

function renderDiff() {
  const from = versions.find((v) => String(v.version) === $("diff-from").value);
  const to = versions.find((v) => String(v.version) === $("diff-to").value);
  const box = $("diff");
  if (!from || !to) { box.replaceChildren(); return; }
  const text = (record) => JSON.stringify(editable(record.template), null, 2);
  const parts = window.SafeGateEditor.lineDiff(text(from), text(to));
  let added = 0;
  let removed = 0;
  const lines = [];
  for (const part of parts) {
    const mark = { added: "+ ", removed: "- ", same: "  " }[part.kind];
    if (part.kind === "added") added += part.lines.length;
    if (part.kind === "removed") removed += part.lines.length;
    for (const line of part.lines) lines.push(el("span", mark + line, "diff-" + part.kind));
  }
  box.replaceChildren(...lines);
  const countLines = (count) => `${count} line${count === 1 ? "" : "s"}`;
  $("diff-summary").textContent = from.version === to.version
    ? "the same version" : `${countLines(removed)} removed, ${added} added`;
}

/** Show a template (as GET /templates/{id} answers it) with its versions ready to compare. */
export function showVersions(template) {
  versions = template.versions || [];
  for (const id of ["diff-from", "diff-to"]) {
    const options = versions.map((record) => {
      const option = el("option", versionLabel(record));
      option.value = String(record.version);
      return option;
    });
    $(id).replaceChildren(...options);
  }
  const last = versions.length - 1;
  $("diff-from").value = String(versions[Math.max(0, last - 1)]?.version ?? "");
  $("diff-to").value = String(versions[last]?.version ?? "");
  renderDiff();
}

export function setupVersions() {
  $("diff-from").addEventListener("change", renderDiff);
  $("diff-to").addEventListener("change", renderDiff);
}
