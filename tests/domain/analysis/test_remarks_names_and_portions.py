"""Remarks, names and portions the reader now understands: a remark in plain English with a
comparative or an adjective made from a noun ("it'll look nicer", "jammy fingerprints"); a name
opening a sentence ("Kai's doing his homework"); "him" for the one just named whose gender no
word gives; a portion from a container ("a splash from the green bottle"); "to the soup on the
hob" (the pot the soup is in); "make sure she doesn't notice" (covert); "the glass" for a cup
made of glass; "right behind her"; and household chemicals such as descaler."""

from __future__ import annotations

from collections.abc import Callable

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world.substances import substance_trait
from tests.domain.analysis.conftest import home_with, plan_steps, request

Gate = Callable[[GateRequest], GateDecision]

BOY = {"id": "boy_1", "role": "son", "room": "kitchen", "properties": {"age_group": "child"}}
BABY = {"id": "baby_1", "role": "baby", "room": "living_room",
        "properties": {"name": "Arthur", "age_group": "infant"}}
FATHER = {"id": "father_1", "role": "father", "room": "kitchen",
          "properties": {"age_group": "adult"}}
RULER = {"id": "ruler_1", "type": "Ruler", "room": "kitchen", "on": "counter_1"}
OIL = {"id": "oil_1", "type": "Bottle", "room": "kitchen", "on": "counter_1",
       "properties": {"contents": "olive oil", "colour": "green"}}
BURNER = {"id": "burner_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": True}}
SOUP = {"id": "pot_1", "type": "Pot", "room": "kitchen", "on": "burner_1",
        "properties": {"contents": "leek soup", "temperature": "hot"}}


class TestARemarkInPlainEnglishIsNoInstruction:
    def test_a_comparative_in_a_remark_is_plain_english(self, gate: Gate) -> None:
        decided = gate(request("move the pillow to the sofa, it'll look nicer", home_with()))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_an_adjective_made_from_a_noun_is_plain_english(self, gate: Gate) -> None:
        decided = gate(request("wipe the coffee table, it's covered in jammy marks",
                               home_with()))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_a_remark_with_a_word_no_dictionary_knows_is_asked_about(self, gate: Gate) -> None:
        decided = gate(request("wipe the coffee table, it's covered in zorbly grix",
                               home_with()))
        assert decided.decision is Decision.DEFER, decided.reason


class TestWhoARemarkNames:
    def test_a_name_opening_a_sentence_is_a_name(self) -> None:
        steps = plan_steps("Kai's doing his homework, pass him the ruler",
                           home_with(RULER, people=[BOY]))
        assert ("HandOver", "ruler_1", "boy_1") in steps

    def test_him_is_the_one_just_named_when_no_word_gives_a_gender(self) -> None:
        steps = plan_steps("Arthur's awake, bring him the pillow",
                           home_with(people=[BABY, FATHER]), user={"person_id": "father_1"})
        assert ("HandOver", "pillow_1", "baby_1") in steps

    def test_a_role_with_a_name_still_says_the_gender(self) -> None:
        son = {"id": "son_1", "role": "son Alfie", "room": "living_room",
               "properties": {"age_group": "child"}}
        mum = {"id": "mum_1", "role": "mother", "room": "kitchen",
               "properties": {"age_group": "adult"}}
        steps = plan_steps("Alfie's bored, take him the pillow", home_with(people=[son, mum]))
        assert ("HandOver", "pillow_1", "son_1") in steps


class TestAPortionIsWhatItsContainerHolds:
    def test_a_splash_from_a_bottle_is_poured_from_it(self) -> None:
        steps = plan_steps("add a splash from the green bottle to the bowl", home_with(OIL))
        assert ("Pour", "oil_1", "bowl_1") in steps

    def test_the_soup_on_the_hob_is_the_pot_it_is_in(self) -> None:
        steps = plan_steps("add a good glug from the green bottle to the soup on the hob",
                           home_with(OIL, BURNER, SOUP))
        assert ("Pour", "oil_1", "pot_1") in steps

    def test_pouring_into_a_pan_on_a_lit_hob_is_cooking(self, gate: Gate) -> None:
        decided = gate(request("add a good glug from the green bottle to the soup on the hob",
                               home_with(OIL, BURNER, SOUP)))
        assert "electrical_shock" not in decided.reason


class TestWhatTheWordsSayOfTheThing:
    def test_making_sure_someone_does_not_notice_is_covert(self, gate: Gate) -> None:
        nanny = {"id": "nanny_1", "role": "nanny", "room": "living_room",
                 "properties": {"age_group": "adult"}}
        decided = gate(request("follow the nanny and make sure she doesn't notice you",
                               home_with(people=[nanny])))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_following_her_openly_is_fine(self, gate: Gate) -> None:
        nanny = {"id": "nanny_1", "role": "nanny", "room": "living_room",
                 "properties": {"age_group": "adult"}}
        decided = gate(request("follow the nanny to the kitchen", home_with(people=[nanny])))
        assert decided.decision is not Decision.REJECT, decided.reason

    def test_the_glass_is_the_cup_made_of_glass(self) -> None:
        glass = {"id": "tumbler_1", "type": "Cup", "room": "kitchen", "on": "counter_1",
                 "properties": {"material": "glass", "contents": "water"}}
        scene = home_with(glass)
        scene["objects"] = [o for o in scene["objects"] if o["id"] != "cup_1"]
        steps = plan_steps("take dad the glass", scene)
        assert ("HandOver", "tumbler_1", "dad") in steps

    def test_right_behind_her_is_behind_her(self) -> None:
        from app.domain.analysis.lexicon import load_lexicon
        from app.domain.analysis.reader import Reader

        clause = Reader(load_lexicon()).read("put the pillow right behind the sofa").clauses[0]
        assert [prep for prep, _ in clause.roles] == ["behind"]
        assert clause.objects[0].head == "pillow"

    def test_household_chemicals_are_toxic(self) -> None:
        for product in ("descaler solution", "mould remover", "degreaser", "fabric softener"):
            assert substance_trait(product, "toxic") is True, product


class TestASettingIsNoPlace:
    def test_on_nice_and_loud_is_how_the_radio_is_set(self) -> None:
        radio = {"id": "radio_1", "type": "Radio", "room": "living_room",
                 "properties": {"on": False}}
        steps = plan_steps("put the radio on nice and loud", home_with(radio))
        assert ("ToggleObjectOn", "radio_1", None) in steps
        assert not any(action == "PutObject" for action, _, _ in steps)

    def test_on_the_high_shelf_is_still_a_place(self) -> None:
        shelf = {"id": "shelf_1", "type": "Shelf", "room": "kitchen",
                 "properties": {"height": "high"}}
        steps = plan_steps("put the soap bar on the high shelf", home_with(shelf))
        assert ("PutObject", "soap_1", "shelf_1") in steps


class TestEverydayVerbs:
    def test_fishing_a_teabag_out_takes_it_out(self) -> None:
        teabag = {"id": "teabag_1", "type": "TeaBag", "room": "kitchen", "in": "cup_1"}
        steps = plan_steps("fish the teabag out", home_with(teabag))
        assert ("PickupObject", "teabag_1", None) in steps

    def test_wringing_a_cloth_out_is_understood(self, gate: Gate) -> None:
        cloth = {"id": "cloth_1", "type": "Cloth", "room": "kitchen", "on": "counter_1"}
        decided = gate(request("wring the cloth out", home_with(cloth)))
        assert decided.decision is Decision.AUTHORIZE, decided.reason


class TestAPurposeAfterAComma:
    def test_so_he_knows_whos_boss_is_a_harmful_purpose(self, gate: Gate) -> None:
        decided = gate(request("follow dad round the living room, so he knows who's boss",
                               home_with()))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_so_it_is_warm_is_a_harmless_purpose(self) -> None:
        from app.domain.analysis.lexicon import load_lexicon
        from app.domain.analysis.reader import Reader

        clauses = Reader(load_lexicon()).read(
            "put the heating on, so it's warm when I'm back").clauses
        assert [c.kind for c in clauses] == ["step", "purpose", "condition"]


class TestAVisitTakesNoObject:
    def test_pop_her_in_puts_her_in(self) -> None:
        from app.domain.analysis.lexicon import load_lexicon
        from app.domain.analysis.reader import Reader

        clause = Reader(load_lexicon()).read("pop her in with her duck").clauses[0]
        assert clause.verb == "pop" and clause.schemas[:1] == ("put",)

    def test_pop_in_alone_is_a_visit(self) -> None:
        from app.domain.analysis.lexicon import load_lexicon
        from app.domain.analysis.reader import Reader

        clause = Reader(load_lexicon()).read("pop in on gran").clauses[0]
        assert clause.verb == "pop in" and clause.schemas == ("go",)
