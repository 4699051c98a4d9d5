// The library table: one page of GET /templates at a time, sorted by the column whose header
// was clicked (again: the other direction), filtered by whole-word search and status. Sorting,
// search and paging all happen on the server, so a page is a slice of the whole sorted list.
import { $, api, el, problemText, debounced } from "./api.js";

const listing = { sort: "id", order: "asc", offset: 0, limit: 20, total: 0, run: 0 };
let selectTemplate = () => {};

// A cell for a dotted or snake_case name that may wrap after its '.' and '_' (never inside a
// word) when the column is narrow.
function nameCell(text, className) {
  const cell = el("td", undefined, className);
  for (const piece of text.split(/(?<=[._])/)) cell.append(piece, el("wbr"));
  return cell;
}

function cells(template) {
  const status = el("td", template.status, "status-" + template.status);
  return [
    nameCell(template.id, "mono"), el("td", template.name),
    nameCell(template.hazard_class),
    el("td", template.severity, "severity-" + template.severity), status,
    el("td", String(template.version), "number"),
  ];
}

function showSortedColumn() {
  for (const header of document.querySelectorAll("#template-table th[data-sort]")) {
    if (header.dataset.sort === listing.sort) {
      header.setAttribute("aria-sort", listing.order === "asc" ? "ascending" : "descending");
    } else {
      header.removeAttribute("aria-sort");
    }
  }
}

function showPosition() {
  const { offset, limit, total } = listing;
  const pages = Math.max(1, Math.ceil(total / limit));
  const current = Math.floor(offset / limit) + 1;
  $("page-position").textContent = `page ${current} of ${pages}`;
  $("page-previous").disabled = offset === 0;
  $("page-next").disabled = offset + limit >= total;
}

export async function loadTemplates() {
  const params = new URLSearchParams({
    sort: listing.sort, order: listing.order,
    offset: String(listing.offset), limit: String(listing.limit),
  });
  if ($("search").value.trim()) params.set("q", $("search").value.trim());
  if ($("status-filter").value) params.set("status", $("status-filter").value);
  const run = ++listing.run;
  const result = await api("GET", "/templates?" + params.toString());
  if (run !== listing.run) return;  // a newer sort, page or search is on its way
  const list = $("template-list");
  if (!result.ok) {
    list.replaceChildren();
    $("template-count").textContent = problemText(result);
    return;
  }
  listing.total = result.data.total;
  if (listing.offset > 0 && listing.offset >= listing.total) {
    listing.offset = Math.max(0, (Math.ceil(listing.total / listing.limit) - 1) * listing.limit);
    return loadTemplates();  // the list shrank under us: show its last page
  }
  const rows = result.data.templates.map((template) => {
    const row = el("tr");
    row.dataset.id = template.id;
    row.tabIndex = 0;
    row.append(...cells(template));
    row.addEventListener("click", () => selectTemplate(template.id));
    row.addEventListener("keydown", (event) => {
      if (event.key === "Enter") selectTemplate(template.id);
    });
    return row;
  });
  list.replaceChildren(...rows);
  const total = result.data.total;
  $("template-count").textContent = `${total} template${total === 1 ? "" : "s"}`;
  showSortedColumn();
  showPosition();
}

function sortBy(column) {
  if (listing.sort === column) {
    listing.order = listing.order === "asc" ? "desc" : "asc";
  } else {
    listing.sort = column;
    listing.order = "asc";
  }
  listing.offset = 0;
  loadTemplates();
}

function fromFirstPage() {
  listing.offset = 0;
  loadTemplates();
}

/** Wire the table's controls; `onSelect(id)` is called when a row is chosen. */
export function setupLibrary(onSelect) {
  selectTemplate = onSelect;
  for (const header of document.querySelectorAll("#template-table th[data-sort]")) {
    header.querySelector("button").addEventListener("click", () => sortBy(header.dataset.sort));
  }
  $("search").addEventListener("input", debounced(fromFirstPage, 250));
  $("status-filter").addEventListener("change", fromFirstPage);
  $("page-size").addEventListener("change", () => {
    listing.limit = Number($("page-size").value);
    fromFirstPage();
  });
  $("page-previous").addEventListener("click", () => {
    listing.offset = Math.max(0, listing.offset - listing.limit);
    loadTemplates();
  });
  $("page-next").addEventListener("click", () => {
    listing.offset += listing.limit;
    loadTemplates();
  });
}
