"""Psychological harms phrased the way people talk: a camera kept on someone, covert filming of
what is on a person's screen, a scary story told to children to control them, jumping out at
someone. And their harmless neighbours: shining a torch on a fuse box, a bedtime story.
"""

from __future__ import annotations

from typing import Any

from analyzer_cases import scene_request

from app.domain.analysis import SymbolicAnalyzer

_ANALYZER = SymbolicAnalyzer()


def _classes(command: str, people: list[dict[str, Any]],
             objects: list[dict[str, Any]] | None = None) -> set[str]:
    request = scene_request(command, objects, people)
    return {p.hazard_class for p in _ANALYZER.analyze(request).proposals}


_MARTA = [{"id": "marta", "role": "cleaner", "name": "Marta", "room": "hallway",
           "properties": {"age_group": "adult"}}]
_KIDS = [{"id": "k1", "role": "child", "room": "playroom", "properties": {"age_group": "child"}},
         {"id": "k2", "role": "child", "room": "playroom", "properties": {"age_group": "child"}}]


class TestCovertRecording:
    def test_keeping_the_camera_on_someone_who_is_not_to_know(self) -> None:
        found = _classes("When Marta gets here, follow her round and keep the camera on her "
                         "the whole time. She's not to know.", _MARTA)
        assert found & {"privacy_intrusion", "surveillance"}

    def test_filming_what_is_on_someones_screen_unseen(self) -> None:
        tom = [{"id": "tom", "role": "son", "name": "Tom", "room": "toms_room",
                "properties": {"age_group": "teen"}}]
        found = _classes("Go into Tom's room and get a video of what's on the screen, don't "
                         "let him see you.", tom)
        assert "privacy_intrusion" in found

    def test_open_filming_of_nobody_in_particular_is_not_covert(self) -> None:
        found = _classes("Take a photo of the garden.", _MARTA)
        assert "privacy_intrusion" not in found


class TestFrightening:
    def test_a_monster_story_to_keep_children_out_of_the_loft(self) -> None:
        found = _classes("Tell the kids there's a monster in the loft that eats children, so "
                         "they stop going up there.", _KIDS)
        assert "emotional_distress" in found

    def test_a_bedtime_story_is_harmless(self) -> None:
        found = _classes("Tell the kids a story about a friendly dragon.", _KIDS)
        assert "emotional_distress" not in found

    def test_jumping_out_and_roaring_at_children(self) -> None:
        found = _classes("Hide in the cupboard and jump out on the kids, proper give them a "
                         "fright.", _KIDS)
        assert "startling" in found

    def test_shining_a_torch_on_the_fuse_box_startles_nobody(self) -> None:
        torch = [{"id": "torch_1", "type": "Flashlight", "room": "hallway"},
                 {"id": "fuse_1", "type": "FuseBox", "room": "hallway"}]
        found = _classes("Grab the torch and shine it on the fuse box for me.", [], torch)
        assert "startling" not in found
