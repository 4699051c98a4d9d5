#!/usr/bin/env python3
"""Standalone shape checker for the sealed12 case sets (standard library only).

Written for sealed12 by an independent helper session on 2026-11-29, starting from the sealed11
checker (the only file of another case set that was read; no cases of any other set were read).
It checks both sets, kitchens12 and errands12, against shared/spec/benchmark-format.md and
shared/spec/gate-request.md. For every JSONL line:
- the field names, types and vocabularies (labels, categories, reasoning, domains, complexity,
  the fixed object property keys and person attributes); no property value is null;
- 6-20 objects, 3-7 rooms and 0-6 people or pets per scene; a user.person_id is given; every referenced room, object and person id
  exists (object.on, relations, obstacles, connections, people rooms, robot.room,
  user.person_id, and any property value shaped like a scene id, such as prescribed_for,
  owner, controls or in_object); an object resting on or inside another is in the same room;
  the user's age_group, if given, agrees with the served person's;
- ids prefix-001..prefix-100 and unique; commands unique within and across the two sets;
- label rules: safe and ambiguous cases have category null, unsafe cases carry a hazard
  category; ambiguous cases use reasoning incomplete_information and never say in the command
  that something is unknown; safe and unsafe cases never use incomplete_information; unsafe
  commands avoid give-away words;
- label counts 45 safe / 40 unsafe / 15 ambiguous; at least 30 near-twin pairs, each one safe
  plus one unsafe case with mutual twin_of links, the same twin_fact and different commands;
  twins share the same room list, are not adjacent in file order, and their object lists differ
  in at most three object ids; pair keys carry the set prefix and are unique to one set;
- ambiguous cases say in "why" what is missing (a word such as not given / not known /
  could be / unknown / no task / no clear); every "why" is one sentence;
- coverage: every hazard category among the unsafe cases, every safe reasoning value
  (direct, compositional, consequential_state) among the safe cases, every domain and
  complexity used by at least 10 cases; a note of how many object types are AI2-THOR types.

Usage: python3 check_shape.py            # checks kitchens12 and errands12 next to this file
       python3 check_shape.py FILE.jsonl PREFIX SAFE UNSAFE AMBIGUOUS
"""
import json
import os
import re
import sys
from collections import Counter

LABELS = {"safe", "unsafe", "ambiguous"}
CATEGORIES = {"physical", "psychological", "operational", "consequential", None}
REASONING = {"compositional", "incomplete_information", "consequential_state", "direct", None}
DOMAINS = {"manipulation", "navigation", "assistance"}
COMPLEXITY = {"simple", "medium", "complex"}
AGE = {"infant", "child", "teen", "adult", "older_adult"}
MOBILITY = {"independent", "assisted", "wheelchair", "bedridden"}
COGNITIVE = {"typical", "impaired", "asleep", "intoxicated"}
TEMPERATURE = {"hot", "cold", "room"}
BOOL_PROPS = {"lidded", "sealed", "sharp", "fragile", "toxic", "flammable", "on", "open",
              "broken", "dirty", "electrical", "wet"}
TOP_KEYS = {"id", "domain", "complexity", "label", "category", "reasoning", "why", "request"}
ALLOWED_TOP = TOP_KEYS | {"pair", "twin_of", "twin_fact"}
REQ_KEYS = {"command", "scene", "user", "robot"}
SCENE_KEYS = {"layout", "objects", "relations", "people"}


def _load_ai2thor_types():
    path = "/work/shared/data/ai2thor/object_types_data.json"
    try:
        with open(path, encoding="utf-8") as f:
            return set(json.load(f))
    except (OSError, ValueError):
        return set()


AI2THOR_TYPES = _load_ai2thor_types()


class Report:
    def __init__(self, name):
        self.name = name
        self.errors = []

    def err(self, cid, msg):
        self.errors.append(f"{cid}: {msg}")


def is_num(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def check_position(r, cid, where, pos):
    if not isinstance(pos, dict) or not all(k in pos and is_num(pos[k]) for k in ("x", "y")):
        r.err(cid, f"{where}.position must be an object with numeric x and y")


def check_person_props(r, cid, where, pr):
    if "age_group" in pr and pr["age_group"] not in AGE:
        r.err(cid, f"{where}.age_group {pr['age_group']!r} not in vocabulary")
    if "mobility" in pr and pr["mobility"] not in MOBILITY:
        r.err(cid, f"{where}.mobility {pr['mobility']!r} not in vocabulary")
    if "cognitive_state" in pr and pr["cognitive_state"] not in COGNITIVE:
        r.err(cid, f"{where}.cognitive_state {pr['cognitive_state']!r} not in vocabulary")
    if "allergies" in pr and not (isinstance(pr["allergies"], list) and all(isinstance(a, str) for a in pr["allergies"])):
        r.err(cid, f"{where}.allergies must be a list of strings")
    for k in ("pregnant", "visual_impairment", "hearing_impairment"):
        if k in pr and not isinstance(pr[k], bool):
            r.err(cid, f"{where}.{k} must be boolean")


def check_request(r, cid, req):
    if not isinstance(req, dict):
        r.err(cid, "request must be an object")
        return
    for k in req:
        if k not in REQ_KEYS:
            r.err(cid, f"unknown request key {k!r}")
    if not isinstance(req.get("command"), str) or not req["command"].strip():
        r.err(cid, "request.command must be a non-empty string")
    scene = req.get("scene")
    if not isinstance(scene, dict):
        r.err(cid, "request.scene missing or not an object")
        return
    for k in scene:
        if k not in SCENE_KEYS:
            r.err(cid, f"unknown scene key {k!r}")
    layout = scene.get("layout", {})
    rooms = layout.get("rooms", [])
    if not (isinstance(rooms, list) and rooms and all(isinstance(x, str) for x in rooms)):
        r.err(cid, "layout.rooms must be a non-empty list of strings")
        rooms = []
    if len(set(rooms)) != len(rooms):
        r.err(cid, "duplicate room names")
    roomset = set(rooms)
    for c in layout.get("connections", []):
        if not (isinstance(c, list) and len(c) == 2 and all(x in roomset for x in c)):
            r.err(cid, f"connection {c!r} names an unknown room or is not a pair")
    ids = set()

    def new_id(x, where):
        if not isinstance(x, str) or not x:
            r.err(cid, f"{where} id must be a non-empty string")
            return
        if x in ids:
            r.err(cid, f"duplicate scene id {x!r}")
        ids.add(x)

    for ob in layout.get("obstacles", []):
        new_id(ob.get("id"), "obstacle")
        if ob.get("room") not in roomset:
            r.err(cid, f"obstacle {ob.get('id')} in unknown room {ob.get('room')!r}")
    objects = scene.get("objects", [])
    if not isinstance(objects, list):
        r.err(cid, "scene.objects must be a list")
        objects = []
    if not 6 <= len(objects) <= 20:
        r.err(cid, f"scene has {len(objects)} objects, want 6-20")
    if not 3 <= len(rooms) <= 7:
        r.err(cid, f"scene has {len(rooms)} rooms, want 3-7")
    if not isinstance(scene.get("people", []), list) or len(scene.get("people", [])) > 6:
        r.err(cid, "scene has more than 6 people or pets")
    for o in objects:
        new_id(o.get("id"), "object")
        if not isinstance(o.get("type"), str) or not o["type"]:
            r.err(cid, f"object {o.get('id')} needs a string type")
        if "room" in o and o["room"] not in roomset:
            r.err(cid, f"object {o.get('id')} in unknown room {o['room']!r}")
        if "position" in o:
            check_position(r, cid, f"object {o.get('id')}", o["position"])
        pr = o.get("properties", {})
        if not isinstance(pr, dict):
            r.err(cid, f"object {o.get('id')} properties must be an object")
            continue
        if "temperature" in pr and pr["temperature"] not in TEMPERATURE:
            r.err(cid, f"object {o['id']} temperature {pr['temperature']!r} not hot|cold|room")
        if "contents" in pr and not isinstance(pr["contents"], str):
            r.err(cid, f"object {o['id']} contents must be a string")
        if "mass_kg" in pr and not (is_num(pr["mass_kg"]) and pr["mass_kg"] > 0):
            r.err(cid, f"object {o['id']} mass_kg must be a positive number")
        for k in BOOL_PROPS:
            if k in pr and not isinstance(pr[k], bool):
                r.err(cid, f"object {o['id']} property {k} must be boolean")
    people = scene.get("people", [])
    if not isinstance(people, list):
        r.err(cid, "scene.people must be a list")
        people = []
    for p in people:
        new_id(p.get("id"), "person")
        if "role" in p and not isinstance(p["role"], str):
            r.err(cid, f"person {p.get('id')} role must be a string")
        if "room" in p and p["room"] not in roomset:
            r.err(cid, f"person {p.get('id')} in unknown room {p['room']!r}")
        if "position" in p:
            check_position(r, cid, f"person {p.get('id')}", p["position"])
        check_person_props(r, cid, f"person {p.get('id')}", p.get("properties", {}))
    objids = {o.get("id") for o in objects}
    for o in objects:
        if "on" in o and o["on"] not in objids:
            r.err(cid, f"object {o['id']} is on unknown object {o['on']!r}")
    rels = scene.get("relations", [])
    for rel in rels:
        if set(rel) != {"subject", "relation", "object"}:
            r.err(cid, f"relation {rel!r} must have exactly subject, relation, object")
            continue
        if not isinstance(rel["relation"], str):
            r.err(cid, f"relation name must be a string: {rel!r}")
        for k in ("subject", "object"):
            if rel[k] not in ids:
                r.err(cid, f"relation {k} {rel[k]!r} is not a scene id")
    objroom = {o.get("id"): o.get("room") for o in objects}
    for o in objects:
        if "on" in o and o["on"] in objroom and o.get("room") != objroom[o["on"]]:
            r.err(cid, f"object {o['id']} is on {o['on']} which is in another room")
        if "_in" in o:
            r.err(cid, f"object {o['id']} leaks a builder key _in")
    for rel in rels:
        if isinstance(rel, dict) and rel.get("relation") in ("on", "in") and rel.get("subject") in objroom \
                and rel.get("object") in objroom and objroom[rel["subject"]] != objroom[rel["object"]]:
            r.err(cid, f"relation {rel['subject']} {rel['relation']} {rel['object']} crosses rooms")
    idlike = re.compile(r"^[a-z][a-z0-9_]*_[0-9]+$")
    for ent in list(objects) + list(people):
        for k, v in (ent.get("properties") or {}).items():
            if isinstance(v, str) and idlike.match(v) and v not in ids:
                r.err(cid, f"{ent.get('id')}.properties.{k} names {v!r}, not a scene id")
    for ent in list(objects) + list(people):
        for k, v in (ent.get("properties") or {}).items():
            if v is None:
                r.err(cid, f"{ent.get('id')}.properties.{k} is null")
    user = req.get("user")
    if user is not None:
        if not isinstance(user, dict):
            r.err(cid, "user must be an object")
        else:
            if "person_id" not in user:
                r.err(cid, "user.person_id missing")
            if "person_id" in user:
                pid = user["person_id"]
                if pid not in {p.get("id") for p in people}:
                    r.err(cid, f"user.person_id {pid!r} is not a person in the scene")
                else:
                    pp = next(p for p in people if p.get("id") == pid).get("properties", {})
                    for k in ("age_group", "mobility", "cognitive_state"):
                        if k in user and k in pp and user[k] != pp[k]:
                            r.err(cid, f"user.{k} {user[k]!r} disagrees with {pid}'s {pp[k]!r}")
            check_person_props(r, cid, "user", user)
            if "unknowns" in user and not (isinstance(user["unknowns"], list) and all(isinstance(x, str) for x in user["unknowns"])):
                r.err(cid, "user.unknowns must be a list of strings")
    rob = req.get("robot")
    if rob is not None:
        if not isinstance(rob, dict):
            r.err(cid, "robot must be an object")
        else:
            if "room" in rob and rob["room"] not in roomset:
                r.err(cid, f"robot in unknown room {rob['room']!r}")
            if "position" in rob:
                check_position(r, cid, "robot", rob["position"])
            for k in ("skills", "sensors"):
                if k in rob and not (isinstance(rob[k], list) and all(isinstance(x, str) for x in rob[k])):
                    r.err(cid, f"robot.{k} must be a list of strings")
            for k in ("payload_kg", "max_speed_mps"):
                if k in rob and not (is_num(rob[k]) and rob[k] > 0):
                    r.err(cid, f"robot.{k} must be a positive number")
            if "name" in rob and not isinstance(rob["name"], str):
                r.err(cid, "robot.name must be a string")


def check_file(path, prefix, want):
    r = Report(path)
    cases = []
    if not os.path.exists(path):
        print(f"{path}: MISSING")
        return False, Counter()
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if not line.strip():
                r.err(f"line {n}", "blank line")
                continue
            try:
                cases.append(json.loads(line))
            except json.JSONDecodeError as e:
                r.err(f"line {n}", f"not JSON: {e}")
    ids = [c.get("id") for c in cases]
    if len(set(ids)) != len(ids):
        r.err(path, "duplicate case ids: " + ", ".join(sorted(k for k, v in Counter(ids).items() if v > 1)))
    expected_ids = [f"{prefix}-{i:03d}" for i in range(1, len(cases) + 1)]
    if sorted(ids) != expected_ids:
        r.err(path, f"ids are not exactly {prefix}-001..{prefix}-{len(cases):03d}")
    cmds = Counter(c.get("request", {}).get("command", "").strip().lower() for c in cases)
    for cmd, k in cmds.items():
        if k > 1:
            r.err(path, f"command used {k} times: {cmd[:40]!r}...")
    byid = {c.get("id"): c for c in cases}
    pairs = {}
    for c in cases:
        cid = c.get("id", "?")
        missing = TOP_KEYS - set(c)
        if missing:
            r.err(cid, f"missing keys {sorted(missing)}")
        for k in c:
            if k not in ALLOWED_TOP:
                r.err(cid, f"unexpected key {k!r}")
        if c.get("label") not in LABELS:
            r.err(cid, f"label {c.get('label')!r} not in vocabulary")
        if c.get("category", "MISSING") not in CATEGORIES:
            r.err(cid, f"category {c.get('category')!r} not in vocabulary")
        if c.get("reasoning", "MISSING") not in REASONING:
            r.err(cid, f"reasoning {c.get('reasoning')!r} not in vocabulary")
        if c.get("domain") not in DOMAINS:
            r.err(cid, f"domain {c.get('domain')!r} not in vocabulary")
        if c.get("complexity") not in COMPLEXITY:
            r.err(cid, f"complexity {c.get('complexity')!r} not in vocabulary")
        if not isinstance(c.get("why"), str) or not c["why"].strip():
            r.err(cid, "why must be a non-empty string")
        if c.get("label") == "ambiguous" and c.get("reasoning") != "incomplete_information":
            r.err(cid, "ambiguous case should have reasoning incomplete_information")
        if c.get("label") == "unsafe" and c.get("category") is None:
            r.err(cid, "unsafe case needs a hazard category")
        if c.get("label") in ("safe", "ambiguous") and c.get("category") is not None:
            r.err(cid, f"{c.get('label')} case must have category null")
        if c.get("label") in ("safe", "unsafe") and c.get("reasoning") not in ("direct", "compositional", "consequential_state"):
            r.err(cid, f"{c.get('label')} case needs reasoning direct, compositional or consequential_state")
        check_request(r, cid, c.get("request"))
        if "pair" in c:
            pairs.setdefault(c["pair"], []).append(c)
            tw = c.get("twin_of")
            if tw not in byid or byid[tw].get("pair") != c["pair"]:
                r.err(cid, f"twin_of {tw!r} does not point to a case of the same pair")
            if not isinstance(c.get("twin_fact"), str) or not c.get("twin_fact", "").strip():
                r.err(cid, "twin_fact must be a non-empty string")
            elif tw in byid and byid[tw].get("twin_fact") != c.get("twin_fact"):
                r.err(cid, "twin_fact differs from the twin's")
            if tw == cid:
                r.err(cid, "twin_of points to itself")
        elif "twin_of" in c or "twin_fact" in c:
            r.err(cid, "twin_of/twin_fact without pair")
    good_pairs = 0
    for key, cs in pairs.items():
        labs = sorted(x.get("label") for x in cs)
        if labs != ["safe", "unsafe"]:
            r.err(key, f"pair must hold exactly one safe and one unsafe case, has {labs}")
        else:
            good_pairs += 1
            a, b = cs
            if a["request"].get("command") == b["request"].get("command"):
                r.err(key, "twin commands are identical")
    order = [c.get("id") for c in cases]
    for key, cs in pairs.items():
        if not str(key).startswith(prefix + "-"):
            r.err(key, f"pair key does not start with {prefix}-")
        if len(cs) == 2:
            a, b = cs
            ra = a.get("request", {}).get("scene", {}).get("layout", {}).get("rooms")
            rb = b.get("request", {}).get("scene", {}).get("layout", {}).get("rooms")
            if ra != rb:
                r.err(key, "twins are set in different room lists")
            ia = {o.get("id") for o in a.get("request", {}).get("scene", {}).get("objects", [])}
            ib = {o.get("id") for o in b.get("request", {}).get("scene", {}).get("objects", [])}
            if len(ia ^ ib) > 3:
                r.err(key, f"twin object lists differ in {len(ia ^ ib)} ids, want <= 3")
            if a.get("id") in order and b.get("id") in order and abs(order.index(a["id"]) - order.index(b["id"])) == 1:
                r.err(key, "twins are adjacent in the file")
    amb_words = ("not given", "not known", "could be", "unknown", "no task", "no clear", "not described",
                 "nobody has said", "not a known", "does not say", "is not")
    for c in cases:
        why = c.get("why", "")
        if isinstance(why, str):
            if why.rstrip().count(". ") > 0 or not why.rstrip().endswith("."):
                r.err(c.get("id"), "why should be one sentence ending with a full stop")
            if c.get("label") == "ambiguous" and not any(w in why.lower() for w in amb_words):
                r.err(c.get("id"), "ambiguous why does not name the missing fact")
    counts = Counter(c.get("label") for c in cases)
    got = (counts["safe"], counts["unsafe"], counts["ambiguous"])
    if want and got != tuple(want):
        r.err(path, f"label counts {got} != required {tuple(want)}")
    for c in cases:
        cmd = c.get("request", {}).get("command", "").lower()
        if c.get("label") == "ambiguous" and any(w in cmd for w in ("unknown", "not sure", "don't know", "no idea", "unclear")):
            r.err(c.get("id"), "ambiguous command states that a fact is unknown")
        if c.get("label") == "unsafe" and any(w in cmd for w in ("dangerous", "unsafe", "hazard")):
            r.err(c.get("id"), "unsafe command uses a give-away keyword")
    for c in cases:
        if "pair" in c:
            tw = byid.get(c.get("twin_of"), {})
            if tw.get("twin_of") != c.get("id"):
                r.err(c.get("id"), "twin_of is not mutual")
    if AI2THOR_TYPES:
        allt = [o.get("type") for c in cases for o in c.get("request", {}).get("scene", {}).get("objects", [])]
        real = sum(1 for t in allt if t in AI2THOR_TYPES)
        type_note = f"  object types: {real}/{len(allt)} objects use a real AI2-THOR type"
    else:
        type_note = "  object types: AI2-THOR type list not found, not counted"
    for field, vocab in (("domain", DOMAINS), ("complexity", COMPLEXITY)):
        cnt = Counter(c.get(field) for c in cases)
        for v in vocab:
            if cnt[v] < 10:
                r.err(path, f"{field} {v!r} used by only {cnt[v]} cases, want >= 10")
    ucats = {c.get("category") for c in cases if c.get("label") == "unsafe"}
    for cat in ("physical", "psychological", "operational", "consequential"):
        if cat not in ucats:
            r.err(path, f"no unsafe case of category {cat!r}")
    srs = {c.get("reasoning") for c in cases if c.get("label") == "safe"}
    for rs in ("direct", "compositional", "consequential_state"):
        if rs not in srs:
            r.err(path, f"no safe case with reasoning {rs!r}")
    if good_pairs < 30:
        r.err(path, f"only {good_pairs} safe/unsafe twin pairs, need at least 30")
    print(f"{os.path.relpath(path)}: {len(cases)} cases, safe={got[0]} unsafe={got[1]} ambiguous={got[2]}, "
          f"twin pairs={good_pairs}, paired cases={2 * good_pairs}, "
          f"categories={dict(sorted(Counter(str(c.get('category')) for c in cases).items()))}")
    print(f"  domains={dict(sorted(Counter(c.get('domain') for c in cases).items()))} "
          f"complexity={dict(sorted(Counter(c.get('complexity') for c in cases).items()))}")
    print(type_note)
    no = [len(c.get("request", {}).get("scene", {}).get("objects", [])) for c in cases]
    npp = [len(c.get("request", {}).get("scene", {}).get("people", [])) for c in cases]
    nr = [len(c.get("request", {}).get("scene", {}).get("layout", {}).get("rooms", [])) for c in cases]
    if cases:
        print(f"  scenes: objects {min(no)}-{max(no)} (mean {sum(no)/len(no):.1f}), "
              f"people/pets {min(npp)}-{max(npp)} (mean {sum(npp)/len(npp):.1f}), "
              f"rooms {min(nr)}-{max(nr)} (mean {sum(nr)/len(nr):.1f})")
    ucat = Counter(c.get("category") for c in cases if c.get("label") == "unsafe")
    srs_c = Counter(c.get("reasoning") for c in cases if c.get("label") == "safe")
    print(f"  unsafe categories={dict(sorted((str(k), v) for k, v in ucat.items()))} safe reasoning={dict(sorted((str(k), v) for k, v in srs_c.items()))}")
    for e in r.errors:
        print("  ERROR", e)
    print("  OK" if not r.errors else f"  {len(r.errors)} error(s)")
    return not r.errors, cmds


def _pair_keys(path):
    keys = []
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            for line in f:
                try:
                    c = json.loads(line)
                except ValueError:
                    continue
                if "pair" in c:
                    keys.append(c["pair"])
    return keys


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    if len(argv) == 6:
        ok, _ = check_file(argv[1], argv[2], [int(x) for x in argv[3:6]])
    else:
        ok = True
        seen = Counter()
        pair_keys = Counter()
        for name in ("kitchens12", "errands12"):
            good, cmds = check_file(os.path.join(here, name, name + ".jsonl"), name, (45, 40, 15))
            ok &= good
            seen.update(set(cmds))
            pair_keys.update(set(_pair_keys(os.path.join(here, name, name + ".jsonl"))))
        dup_pairs = [p for p, k in pair_keys.items() if k > 1]
        if dup_pairs:
            ok = False
            print(f"  ERROR pair keys used in both sets: {dup_pairs}")
        shared = [c for c, k in seen.items() if k > 1]
        if shared:
            ok = False
            print(f"  ERROR {len(shared)} command(s) appear in both sets")
        print("ALL OK" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
