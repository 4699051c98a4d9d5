"""Grounding people: which person (or pet) of the scene a phrase names.

In: a `NounPhrase`. Out: a `Referent` of the person: by name, role, title, kinship or pronoun;
the one unnamed person a name the scene lists for nobody points to ("hand Noah the scissors"); a
pet by its name or kind; a new person a role word names ("the guest"). Remembers who "him" and
"her" point to next. `Grounder` (grounding.py) adds the objects and places. Fails: never.
"""

from __future__ import annotations

from app.domain.analysis.lexicon import Lexicon, PersonWord
from app.domain.analysis.phrases import TITLES, NounPhrase
from app.domain.analysis.referents import GENERIC_WORDS, MAX_GROUP, USER_ID, Referent, words_of
from app.domain.models import GateRequest
from app.domain.world import ObjectState, PersonState, WorldState
from app.domain.world.concepts import singular
from app.domain.world.entities import frozen_mapping
from app.domain.world.object_types import normalize_type


class PeopleGrounding:
    """The people half of `Grounder`: the state it reads is set up by `Grounder.__init__`."""

    lexicon: Lexicon
    objects: dict[str, ObjectState]
    people: dict[str, PersonState]
    rooms: list[str]
    last_person: dict[str | None, str]
    _given_names: frozenset[str]
    _pet_names: dict[str, str]
    _base: WorldState
    _request: GateRequest
    _user_id: str | None
    _names: dict[str, set[str]]
    _mentions: int
    _last_person_at: int
    _last_animal: tuple[str, int] | None

    def _names_a_product(self, phrase: NounPhrase) -> bool:
        """Whether a scene object answers to the phrase (the object side decides)."""
        raise NotImplementedError

    @property
    def user_id(self) -> str:
        """The person giving the command: the profile's person, else one added on first use
        (an adult unless the profile says otherwise; where they are is unknown)."""
        if self._user_id is None:
            self._user_id = self._user(self._request)
        return self._user_id

    def _user(self, request: GateRequest) -> str:
        user = request.user
        if user is not None and user.person_id and user.person_id in self.people:
            return user.person_id
        age = user.age_group if user is not None and user.age_group else "adult"
        properties: dict[str, object] = {"age_group": age}
        if user is not None:
            properties.update({k: v for k, v in (("mobility", user.mobility),
                               ("cognitive_state", user.cognitive_state),
                               ("allergies", user.allergies)) if v is not None})
        self.people[USER_ID] = PersonState(id=USER_ID, role="user",
                                           properties=frozen_mapping(properties))
        self._names[USER_ID] = {"user", "me"}
        return USER_ID

    def names_of_people(self) -> set[str]:
        """Every word that names a person of the scene (ids, names, roles)."""
        return set().union(*self._names.values()) if self._names else set()

    def person(self, phrase: NounPhrase) -> Referent:
        """A phrase that must name a person (a recipient, someone escorted)."""
        found = self._person(phrase) or self._animal(phrase)
        if found is not None:
            return found
        return self._new_person(phrase)

    def _possessor(self, possessor: str) -> Referent | None:
        """The person a possessor names ("her", "mum", "Sam")."""
        return self._person(NounPhrase(possessor, head=possessor, pronoun=possessor if (
            possessor in ("me", "him", "her", "them", "us")) else None))

    def _animal(self, phrase: NounPhrase) -> Referent | None:
        """A pet the scene lists, named or by its kind ("Biscuit", "the dog")."""
        aliased = self._pet_names.get(phrase.phrase)
        if aliased is not None:
            return Referent(phrase, "object", (aliased,))
        words = words_of(phrase.phrase or phrase.text)
        found = tuple(i for i, o in self.objects.items()
                      if self._base.value("animal", (i,)) is True and words & (words_of(
                          o.name, o.type, *(str(o.properties.get(k, "")) for k in (
                              "name", "species"))) - GENERIC_WORDS))
        return Referent(phrase, "object", found[:1]) if found else None

    def _person(self, phrase: NounPhrase) -> Referent | None:
        word = phrase.pronoun or phrase.phrase
        if word in ("me", "i", "myself", "us", "we"):
            return self._remember_person(Referent(phrase, "person", (self.user_id,)))
        pet = self._last_animal
        if phrase.pronoun in ("him", "her") and pet is not None and pet[1] > self._last_person_at:
            return Referent(phrase, "object", (pet[0],))
        if phrase.pronoun in ("him", "her", "them", "himself", "herself"):
            gender = {"him": "male", "himself": "male", "her": "female",
                      "herself": "female"}.get(phrase.pronoun)
            last = self.last_person.get(gender)
            named = self.last_person.get(None)
            if last is None and named is not None and (
                    gender is None or self._gender(named) is None):
                last = named  # "Arthur's teething, give him ...": the one just named
            if last is not None:
                return Referent(phrase, "person", (last,))
            matches = [p for p in self.people if p != self._user_id
                       and (gender is None or self._gender(p) in (gender, None))]
            if len(matches) == 1:
                return self._remember_person(Referent(phrase, "person", (matches[0],)))
            if matches:
                return Referent(phrase, "person", (), tuple(matches))
            return None
        if phrase.pronoun in ("everyone", "everybody", "people"):
            user = self.user_id  # may add the speaker to the people: look first
            ids = tuple(p for p in self.people if p != user)
            return Referent(phrase, "person", ids) if ids else None
        if not phrase.head:
            return None
        wanted = words_of(phrase.phrase)
        matches = [pid for pid, names in self._names.items() if wanted and wanted <= names]
        if not matches and not self._names_a_product(phrase):
            matches = [pid for pid, names in self._names.items() if phrase.head in names
                       or singular(phrase.head) in names]
        if not matches and len(phrase.modifiers) == 1 and phrase.modifiers[0] in \
                self.lexicon.people and len(phrase.text.split()) == 2:
            # "uncle Ray" when the scene lists an uncle by no name: the uncle
            matches = [pid for pid, names in self._names.items() if phrase.modifiers[0] in names]
        if not matches:
            info = self.lexicon.people.get(phrase.phrase) or self.lexicon.people.get(
                phrase.head)
            if info is None and phrase.phrase.split()[0] in TITLES:
                return self._titled(phrase)
            if info is None and phrase.phrase in self._given_names:
                return self._unnamed(phrase, gender=None, kin=True)
            if info is None or info.is_user or self._names_a_product(phrase):
                return None
            matches = [p.id for p in self.people.values() if info.age_group
                       and p.properties.get("age_group") == info.age_group
                       and info.role in ("baby", "toddler", "child", "teen")]
            if not matches:
                matches = [p.id for p in self.people.values() if self._same_kind(p.role, info)]
            if not matches:
                return None
        ids = tuple(matches[:MAX_GROUP]) if (phrase.every or (phrase.head.endswith("s")
                                             and len(matches) > 1)) else tuple(matches[:1])
        if len(matches) > 1 and len(ids) == 1 and not phrase.every:
            return Referent(phrase, "person", (), tuple(matches))
        titled = TITLES.get(phrase.phrase.split()[0]) if phrase.phrase else None
        if titled is not None and len(ids) == 1:
            self.last_person[titled] = ids[0]  # "Mrs Ade ... her arm": the title says who
        return self._remember_person(Referent(phrase, "person", ids))

    def _same_kind(self, role: str | None, wanted: PersonWord) -> bool:
        """Whether a scene role is another word for the same kind of person ("grandad" and
        a "grandfather", never a "grandmother")."""
        info = self.lexicon.people.get((role or "").lower())
        return info is not None and info.role == wanted.role and not info.is_user and (
            info.gender is None or wanted.gender is None or info.gender == wanted.gender)

    def _titled(self, phrase: NounPhrase) -> Referent | None:
        """ "Mr Adeyemi" when the scene lists nobody by that name: the one unnamed person of
        that title's gender who is no kin of the speaker (see `_unnamed`)."""
        return self._unnamed(phrase, TITLES[phrase.phrase.split()[0]], kin=False)

    def _unnamed(self, phrase: NounPhrase, gender: str | None, *, kin: bool) -> Referent | None:
        """A name the scene lists for nobody: the one person the scene describes without a
        name (the caller described who is there); several are a question, none a person the
        scene lacks."""
        user = self._request.user
        speaker = user.person_id if user is not None and user.person_id else self._user_id
        unnamed = [pid for pid, person in self.people.items() if pid != speaker
                   and not person.name and not person.properties.get("name")
                   and (kin or not self._is_kin(person.role))
                   and (gender is None or self._gender(pid) in (gender, None))]
        if len(unnamed) == 1:
            if gender is not None:  # "Mr Dunn ... shake him": the title says who "him" is
                self.last_person[gender] = unnamed[0]
            return self._remember_person(Referent(phrase, "person", (unnamed[0],)))
        return Referent(phrase, "person", (), tuple(unnamed)) if unnamed else None

    def _is_kin(self, role: str | None) -> bool:
        info = self.lexicon.people.get((role or "").lower())
        return info is not None and info.kin

    def _gender(self, person_id: str) -> str | None:
        person = self.people[person_id]
        for words in (person.role, person.name):
            # "son Alfie": the role's word for a kind of person says it
            for word in ([words.lower(), *words.lower().split()] if words else []):
                info = self.lexicon.people.get(word)
                if info is not None and info.gender:
                    return info.gender
        gender = person.properties.get("gender")
        return gender if isinstance(gender, str) else None

    def _remember_person(self, referent: Referent) -> Referent:
        self._mentions += 1
        self._last_person_at = self._mentions
        for person_id in referent.ids:
            self.last_person[None] = person_id
            gender = self._gender(person_id)
            if gender:
                self.last_person[gender] = person_id
        return referent

    def _new_person(self, phrase: NounPhrase) -> Referent:
        role = phrase.phrase or phrase.text or "person"
        info = self.lexicon.people.get(role) or self.lexicon.people.get(phrase.head)
        properties = {"age_group": info.age_group} if info is not None and info.age_group else {}
        person_id = f"new_{normalize_type(role) or 'person'}"
        self.people[person_id] = PersonState(id=person_id, role=role,
                                             properties=frozen_mapping(properties))
        self._names[person_id] = words_of(role)
        return self._remember_person(Referent(phrase, "person", (person_id,), new=True))

    # Objects.
