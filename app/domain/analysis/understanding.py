"""Stage 1, step 1 (read): the command understood as steps of the action model on the scene.

In: a `GateRequest` and the lexicon. Out: `Understanding`: the scene (the request's `WorldState`
plus what the command named that the scene lacked), the `Sketch` of the plan the command induces,
the grounded clauses, the condition and purpose clauses, the manner cues, the declared rules that
fired and the `comprehension` unknowns: an unknown verb or noun, a pronoun with nothing to point
to, a goal with no task, several things a phrase may mean that differ in what is safe. A remark
said beside a task ("it's all sticky") is not a task and asks nothing; the same words alone are
all the command says, so the gate asks what to do. Fails: never.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field, replace

from app.domain.analysis.arguments import STARTING_VERBS, Clause
from app.domain.analysis.declared import RULES, Declared, declared, harm_stated
from app.domain.analysis.grounding import Grounder
from app.domain.analysis.handlers import apply_clause
from app.domain.analysis.horizon import hours_left_standing, who_sleeps
from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.names import scene_names
from app.domain.analysis.phrases import TIME_UNITS
from app.domain.analysis.questions import not_understood, which_one
from app.domain.analysis.reader import Reader, sounds_like_statement
from app.domain.analysis.schemas import Grounded, ground_clause
from app.domain.analysis.sketch import Sketch
from app.domain.analysis.specifications import specifications
from app.domain.analysis.steps import PlanBuilder
from app.domain.models import GateRequest, UnknownFact
from app.domain.world import WorldState, state_from_request
from app.domain.world.entities import frozen_mapping


@dataclass
class Understanding:
    """What Stage 1 read from a command (see the module docstring)."""

    scene: WorldState
    sketch: Sketch
    grounded: list[Grounded] = field(default_factory=list)
    others: list[Clause] = field(default_factory=list)
    manner: frozenset[str] = frozenset()
    unknowns: list[UnknownFact] = field(default_factory=list)
    fired: list[Declared] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def understand(request: GateRequest, lexicon: Lexicon) -> Understanding:
    """Read a command into the induced plan on its scene.

    Args:
        request: the gate request.
        lexicon: the reader's vocabulary.

    Returns:
        The understanding; its `unknowns` list what could not be read.
    """
    state = state_from_request(request)
    named = scene_names(request.command, state, lexicon)
    names, proper, given, pets = named.names, named.proper, named.given, named.pets
    reading = Reader(lexicon, names | given | set(pets), named.animals).read(
        request.command)
    grounder = Grounder(state, request, lexicon, given_names=given, pet_names=pets)
    builder = PlanBuilder(grounder)
    unknowns: list[UnknownFact] = []
    grounded: list[Grounded] = []
    others: list[Clause] = []
    actionable = any(c.kind == "step" and c.schemas and c.schemas != ("goal",)
                     for c in reading.clauses)
    found = specifications(reading.clauses, lexicon, _unreadable)
    for made, added in found.values():
        builder.ingredients[made] = added
    for index, clause in enumerate(reading.clauses):
        if index in found:
            others.append(clause)  # "make Dad a cuppa - milk, one sugar": what goes in it
            continue
        if clause.kind == "heading" and not harm_stated(clause.text, lexicon):
            grounder.remember(clause.text)  # "Leo's party tea:" names things, asks nothing
            others.append(clause)
            continue
        if clause.kind not in ("step", "heading"):
            others.append(clause)
            continue
        if _leave_as_is(clause):
            continue  # "leave it", "leave the mess": a manner cue for the rest, not a step
        problem = _unreadable(clause, lexicon)
        if problem is not None and actionable and _remark(clause, lexicon, names | proper):
            grounder.remember(clause.text)
            others.append(clause)
            continue
        if problem is not None:
            unknowns.append(not_understood(clause.text, problem))
            continue
        item = ground_clause(builder, clause, index)
        if clause.negated:
            _cancel(grounded, item)
        grounded.append(item)
    _mark_carried_on(grounded)
    _fold_cooking_times(grounded)
    idle: list[Grounded] = []
    for item in grounded:
        if not item.cancelled:
            before = len(builder.sketch.literal) + len(builder.notes)
            apply_clause(builder, item)
            if len(builder.sketch.literal) + len(builder.notes) == before and _acts(item):
                idle.append(item)
    leaving = _leaving(request.command, grounder)
    hours = hours_left_standing(request.command)
    if (leaving or hours) and any(True for _ in builder.sketch.steps()):
        # "I'm off to work", "so it's hot when we get back": the speaker is out meanwhile;
        # "overnight", "all weekend": the result stands that long by itself
        meanwhile = {"away": ",".join(leaving)} if leaving else {}
        sleeping = who_sleeps(request.command)
        if sleeping is not None:
            meanwhile["asleep"] = grounder.user_id if sleeping == "i" else ",".join(
                grounder.people)
        builder.sketch.stands = builder.act("Wait", kind="enabling",
                                            seconds=3600.0 * (hours or 1.0), **meanwhile)
    builder.sketch.fast = "fast" in reading.manner
    builder.sketch.leave = "leave" in reading.manner or _kept_going(reading.clauses)
    builder.sketch.running = _started_to_run(reading.clauses)
    scene = grounder.scene()
    unknowns += [not_understood(g.words, g.why) for g in grounder.gaps]
    unknowns += [not_understood(i.clause.text, "no step the robot could take for it")
                 for i in idle if not any(g.words in i.clause.text for g in grounder.gaps)]
    unknowns += [not_understood(detail, "a step the command asks for cannot run on this scene")
                 for detail in dict.fromkeys(builder.failed)]
    unknowns += _ambiguities(grounded, scene)
    fired = declared(grounded, others, reading.manner, lexicon)
    fired += [Declared("harmful_goal", RULES["harmful_goal"].template_id, {}, c.text)
              for c in reading.clauses if c.kind == "step" and "goal" in c.schemas[:1]
              and harm_stated(c.text, lexicon)]
    return Understanding(scene, builder.sketch, grounded, others, reading.manner, unknowns,
                         fired, builder.notes)


_CONTRACTION = re.compile(r"'(ll|re|ve|d|m|s|t)\b")
_KEEP_STATES = frozenset({"going", "on", "running", "burning", "lit", "open", "charging",
                          "hot", "warm", "plugged"})
_STILL_RUNNING = frozenset({"heats", "heating", "cooks", "cooking", "boils", "boiling",
                            "warms", "warming", "bakes", "baking", "simmers", "simmering",
                            "fills", "filling", "runs", "running", "charges", "charging",
                            "defrosts", "defrosting", "thaws", "preheats", "preheating",
                            "roasts", "roasting", "fries", "frying"})
_RETURN_WORDS = frozenset({"back", "home", "return", "returns", "get", "later", "morning",
                           "overnight", "tomorrow", "tonight"})


def _kept_going(clauses: tuple[Clause, ...]) -> bool:
    """Whether the command wants what it starts left as it is ("keep them going till I'm
    home", "so it's hot when I'm back"): then no careful plan switches it off at the end."""
    returning = kept = False
    for clause in clauses:
        if clause.kind == "step" and clause.verb in ("preheat", "pre-heat"):
            return True  # an oven is preheated to be hot when the cooking starts, later
        words = set(clause.text.replace("'", " ").split())
        if clause.kind == "step" and clause.verb in ("keep", "leave") and (
                clause.complement in _KEEP_STATES or words & _KEEP_STATES):
            return True
        if clause.kind == "condition" and clause.opener in ("while", "whilst") and \
                words & _STILL_RUNNING:
            return True  # "go hoover upstairs while it heats up": it runs while the robot is away
        if clause.kind in ("condition", "purpose"):
            returning = returning or (bool(words & _RETURN_WORDS) and clause.opener in (
                "till", "until", "when", "so", "so that", "for when"))
            kept = kept or bool(words & _KEEP_STATES) or clause.opener in ("till", "until")
    return returning and kept


def _fold_cooking_times(grounded: list[Grounded]) -> None:
    """ "Heat up the soup. Two minutes in the microwave should do it": a clause that only
    names a length of time in a place says where and how long the clause before it cooks,
    and is no step of its own."""
    for first, then in itertools.pairwise(grounded):
        timed = bool(then.clause.objects) and all(
            (np.head or "") in TIME_UNITS for np in then.clause.objects)
        if first.schema == "heat" and timed and then.destination is not None and \
                then.destination.ids and not then.destination.new and not then.cancelled and (
                first.destination is None or not first.destination.ids):
            first.destination = then.destination
            then.cancelled = True


def _mark_carried_on(grounded: list[Grounded]) -> None:
    """A fetch whose things the very next clause puts or gives somewhere only carries them."""
    for first, then in itertools.pairwise(grounded):
        fetched = {i for r in first.objects for i in r.ids}
        placed = {i for r in then.objects for i in r.ids}
        if first.schema == "fetch" and then.schema in ("put", "give") and fetched & placed \
                and first.recipient is None and first.destination is None:
            first.carried_on = True


def _started_to_run(clauses: tuple[Clause, ...]) -> frozenset[int]:
    """The clauses that set something going for the rest of the task: "start the sink
    filling, then ...", "get the engine running and ...": a process started so that it runs
    while the robot does the next thing, which switching it straight off would defeat."""
    started: set[int] = set()
    for index, clause in enumerate(clauses):
        if clause.kind != "step" or (clause.verb or "").split(" ")[0] not in STARTING_VERBS:
            continue
        words = set(clause.text.replace("'", " ").split())
        if clause.verb == "start" or words & (_STILL_RUNNING | {"going"}):
            started.add(index)
    return frozenset(started)


_SPEAKER_LEAVES = re.compile(
    r"\b(?:(i|we)(?:'m|'re| am| are)(?: all| just| only| about to| going to)? (?:off\b|going out|"
    r"heading out|heading off|heading to|leaving|out (?:all|for|till|until)\b|"
    r"out for|away for|going to (?:work|bed|the)|going away|"
    r"(?:popping|nipping|running|dashing|stepping|slipping|pop|nip|run|dash|step|slip) "
    r"(?:out\b(?! of)|to the|off|round to|down to|over to|into town))"
    r"|(?:when|till|until|before) (i|we)(?: get| come)? (?:back|home|return)"
    r"|(?:when|till|until) (i|we)(?:'m|'re| am| are) (?:back|home)"
    r"|while (i|we)(?:'m|'re| am| are) (?:out|away|gone|at work|asleep|in bed)"
    r"|(?:when|once|as|after|before) (i|we)(?:'ve| have)? (?:go|leave|left|gone|head off|"
    r"head out|go out|go to bed|turn in|get going)\b(?! up| upstairs| down| through| in))")


def _leaving(command: str, grounder: Grounder) -> tuple[str, ...]:
    """Who the command says will be out of the home (or in bed) while the task's result
    stands: the speaker for "I", the adults of the household for "we"."""
    found = _SPEAKER_LEAVES.search(command.lower().replace("\u2019", "'"))
    if found is None:
        return ()
    speaker = next(g for g in found.groups() if g)
    known = grounder.people.keys()
    user = grounder.user_id
    if user not in known or grounder.people[user].properties.get("cognitive_state") is None:
        # Someone heading out to work or the match is awake and alert.
        person = grounder.people[user]
        grounder.people[user] = replace(person, properties=frozen_mapping(
            {**person.properties, "cognitive_state": "alert"}))
    if speaker == "i":
        return (user,)
    adults = [p.id for p in grounder.people.values()
              if p.properties.get("age_group") in ("adult", "older_adult", None)]
    return tuple(dict.fromkeys([grounder.user_id, *adults]))


def _acts(item: Grounded) -> bool:
    """Whether a clause asks for an action that must show up as steps: it names someone to
    move or something to act on ("get grandma into the shower", "empty the bins"), not a wait,
    a leave-be or a "don't". One that yields no step is not understood, never dropped."""
    return item.schema not in (None, "wait", "goal", "stay", "chore") and \
        not item.clause.negated and any(
            r.kind == "person" or (r.kind == "object" and r.ids) for r in item.objects)


def _cancel(earlier: list[Grounded], negation: Grounded) -> None:
    """ "chuck us the scissors - well don't chuck them, hand them over": a negated step takes
    back an earlier step of the same schema on the same things."""
    targets = {i for r in negation.objects for i in r.ids}
    for item in earlier:
        if item.schema == negation.schema and not item.clause.negated and (
                not targets or targets & {i for r in item.objects for i in r.ids}):
            item.cancelled = True


def _unreadable(clause: Clause, lexicon: Lexicon) -> str | None:
    if clause.verb is None:
        return "no action verb (a statement or a wish, not an instruction)"
    if not clause.schemas:
        known = lexicon.is_english(clause.verb.split()[0])
        return (f"'{clause.verb}' is not an action this robot has" if known
                else f"'{clause.verb}' is not a word I know")
    if clause.schemas == ("goal",) and not harm_stated(clause.text, lexicon):
        return "a goal, not a task: it does not say what to do"
    return None


def _remark(clause: Clause, lexicon: Lexicon, names: set[str]) -> bool:
    """A verbless remark or a vague goal beside a task: plain English (or the scene's names),
    no harm, and nothing about someone's health or needs (that is for the gate to apply, or
    to ask about)."""
    if (clause.schemas and clause.schemas != ("goal",)) or (
            clause.verb is not None and not clause.schemas and (clause.objects or clause.roles)
            and not sounds_like_statement(clause.text)
            and lexicon.lemma(clause.verb.split()[0]) == clause.verb.split()[0]):
        return False  # "wedge the door open": an instruction in words the robot lacks
    words = [w for w in _CONTRACTION.sub("", clause.text).replace("'", " ").split()
             if w.isalpha()]
    if {w.lower() for w in words} & lexicon.health_words:
        return False
    return all(lexicon.is_english_form(w) or w in names for w in words) and not harm_stated(
        clause.text, lexicon)


def _leave_as_is(clause: Clause) -> bool:
    # "leave it", "leave the mess" (not "leave it open": a state to keep is a step)
    return clause.verb in ("leave", "keep") and clause.complement is None and not any(
        prep not in ("on", "in") for prep, _ in clause.roles) and all(
        o.pronoun is not None or o.head in ("mess", "everything", "rest", "things", "stuff")
        for o in clause.objects)


def _ambiguities(grounded: list[Grounded], scene: WorldState) -> list[UnknownFact]:
    found: list[UnknownFact] = []
    for item in grounded:
        # "turn off the stove" with four burners: switching every one off is the safe reading
        objects = () if item.schema == "switch_off" and not item.clause.negated else item.objects
        for ref in (*objects, item.recipient, item.destination, item.source):
            if ref is not None and not ref.ids and len(ref.candidates) > 1:
                found.append(which_one(ref.phrase.text, list(ref.candidates), scene))
    return found
