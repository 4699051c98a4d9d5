// What every part of the curator page shares: the API key of the session, JSON calls to the API
// and building DOM nodes from API text (always as text, never as HTML).

export const $ = (id) => document.getElementById(id);

export const session = { key: sessionStorage.getItem("safegate-key") || "" };

export function el(tag, text, className) {
  const node = document.createElement(tag);
  if (text !== undefined && text !== null) node.textContent = text;
  if (className) node.className = className;
  return node;
}

export async function api(method, path, body) {
  const headers = { "Accept": "application/json" };
  if (session.key) headers["Authorization"] = "Bearer " + session.key;
  if (body !== undefined) headers["Content-Type"] = "application/json";
  const response = await fetch(path, {
    method, headers, body: body === undefined ? undefined : JSON.stringify(body),
  });
  let data = null;
  try { data = await response.json(); } catch (_) { data = null; }
  return { ok: response.ok, status: response.status, data };
}

export function problemText(result) {
  const data = result.data || {};
  return `${result.status} ${data.title || "error"}: ${data.detail || ""}`;
}

export function showResult(text, className) {
  const box = $("result");
  box.textContent = text;
  box.className = className || "";
}

// Calls `action` once input has paused for `delay` ms.
export function debounced(action, delay) {
  let timer = null;
  return (...args) => {
    clearTimeout(timer);
    timer = setTimeout(() => action(...args), delay);
  };
}
