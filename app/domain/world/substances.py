"""What a substance is: a liquid, food, toxic, flammable, a common allergen, medication.

In: a `contents` string from a request or an effect ("hot coffee", "bleach", "peanut butter").
Out: `substance_trait(contents, trait)` -> True, False, or None when the substance is not
recognised; `is_empty(contents)`; `same_substance(a, b)` for allergy and `contains` matching.
Fails: never; an unrecognised substance answers None, so facts that depend on it stay unknown.
"""

from __future__ import annotations

import re
from functools import cache
from itertools import pairwise

TRAITS = ("liquid", "food", "toxic", "flammable", "allergen", "medication")

_SUBSTANCES: dict[str, frozenset[str]] = {
    name: frozenset(traits.split())
    for names, traits in (
        ("water ice", "liquid"),
        ("coffee tea juice soup broth vinegar cocoa lemonade soda", "liquid food"),
        ("wine beer whisky whiskey vodka gin rum brandy sherry cider lager", "liquid food"),
        ("milk cream yogurt", "liquid food allergen"),
        ("oil cooking_oil olive_oil vegetable_oil", "liquid food flammable"),
        ("bleach ammonia detergent dish_soap soap cleaner disinfectant drain_cleaner antifreeze "
         "pesticide acid lye shampoo window_cleaner descaler degreaser unblocker remover "
         "solvent sanitiser sanitizer caustic softener", "liquid toxic"),
        # Products named for what they kill or keep away ("ant killer", "slug pellets").
        ("killer weedkiller insecticide herbicide repellent rodenticide poison pellets "
         "fungicide", "toxic"),
        ("alcohol rubbing_alcohol ethanol isopropyl gasoline petrol kerosene lighter_fluid "
         "paint_thinner acetone", "liquid toxic flammable"),
        ("peanut peanuts peanut_butter nut nuts almond almonds walnut cashew egg eggs wheat "
         "flour gluten shellfish shrimp fish soy sesame satay pesto praline marzipan nutella "
         "hazelnut pistachio pecan prawn prawns crab lobster mussels clams oysters scampi "
         "tahini hummus houmous halva salmon tuna cod haddock mackerel sardines anchovies "
         "soya edamame miso mayonnaise meringue custard",
         "food allergen"),
        ("bread cereal pasta rice sugar salt candy fruit apple banana vegetable cookie "
         "cookies cake chocolate cheese chicken beef pork lamb meat sausage bacon ham turkey "
         "curry stew chowder salad sandwich pizza burger noodles sauce gravy porridge oats "
         "jam honey butter biscuit biscuits crisps grapes grape orange berries potato "
         "potatoes beans lentils tofu omelette pancake pancakes toast leftovers dinner lunch "
         "breakfast", "food"),
        # What pets are fed: food, though not for people.
        ("kibble dog_food cat_food pet_food fish_food flakes birdseed hay pellet_food "
         "treats chews", "food"),
        ("pills pill medicine medication tablets ibuprofen aspirin paracetamol acetaminophen "
         "insulin antibiotics vitamins warfarin codeine diazepam naproxen sleeping_pills "
         "vaccine vaccines eye_drops inhaler epipen morphine co-codamol tramadol prescription",
         "medication"),
        ("paper", "flammable"),
    )
    for name in names.split()
}
# An allergen family a person may name, and the substances that belong to it.
_FAMILIES: dict[str, frozenset[str]] = {
    "peanut": frozenset({"peanut", "peanuts", "peanut_butter", "satay"}),
    "nut": frozenset({"nut", "nuts", "almond", "almonds", "walnut", "cashew", "peanut",
                      "hazelnut", "pistachio", "pecan", "pesto", "praline", "marzipan",
                      "nutella", "satay"}),
    "tree_nut": frozenset({"almond", "almonds", "walnut", "cashew", "hazelnut", "pistachio",
                           "pecan", "pesto", "praline", "marzipan", "nutella"}),
    "shellfish": frozenset({"shellfish", "shrimp", "prawn", "prawns", "crab", "lobster",
                            "mussels", "clams", "oysters", "scampi"}),
    "dairy": frozenset({"milk", "cream", "yogurt", "cheese", "butter", "custard"}),
    "milk": frozenset({"milk", "cream", "yogurt", "cheese", "butter", "custard"}),
    "egg": frozenset({"egg", "eggs", "mayonnaise", "meringue", "omelette", "custard"}),
    "sesame": frozenset({"sesame", "tahini", "hummus", "houmous", "halva"}),
    "fish": frozenset({"fish", "salmon", "tuna", "cod", "haddock", "mackerel", "sardines",
                       "anchovies"}),
    "soy": frozenset({"soy", "soya", "tofu", "edamame", "miso"}),
    "gluten": frozenset({"wheat", "flour", "gluten", "bread", "pasta", "cake", "cookie"}),
    "wheat": frozenset({"wheat", "flour", "bread", "pasta"}),
}
# Medicine and drink classes, and the pairs that are dangerous taken together (bleeding,
# breathing slowed, a drug level raised): the combinations pharmacists warn of first.
_DRUG_CLASSES: dict[str, frozenset[str]] = {
    "nsaid": frozenset({"aspirin", "ibuprofen", "naproxen", "diclofenac", "nsaid", "nurofen",
                        "advil", "anadin"}),
    "anticoagulant": frozenset({"warfarin", "apixaban", "rivaroxaban", "dabigatran", "edoxaban",
                                "heparin", "clopidogrel", "blood_thinner", "anticoagulant",
                                "coumadin", "eliquis", "xarelto"}),
    "sedative": frozenset({"sleeping_pill", "sleeping_tablet", "diazepam", "lorazepam",
                           "temazepam", "zopiclone", "zolpidem", "benzodiazepine", "codeine",
                           "tramadol", "morphine", "oxycodone", "opioid", "sedative",
                           "valium", "gabapentin", "pregabalin"}),
    "alcohol": frozenset({"wine", "beer", "whisky", "whiskey", "vodka", "gin", "rum", "brandy",
                          "sherry", "cider", "lager", "spirits", "liquor", "prosecco",
                          "champagne", "port", "alcohol"}),
    "statin": frozenset({"simvastatin", "atorvastatin", "lovastatin", "statin"}),
    "grapefruit": frozenset({"grapefruit", "grapefruit_juice"}),
    "metronidazole": frozenset({"metronidazole", "flagyl"}),
    "maoi": frozenset({"phenelzine", "tranylcypromine", "maoi", "selegiline"}),
    "decongestant": frozenset({"pseudoephedrine", "decongestant", "sudafed"}),
}
_INTERACTING = frozenset(frozenset(pair) for pair in (
    ("nsaid", "anticoagulant"), ("alcohol", "sedative"), ("sedative", "sedative"),
    ("statin", "grapefruit"), ("alcohol", "metronidazole"), ("maoi", "decongestant"),
    ("alcohol", "anticoagulant"),
))
_EMPTY = frozenset({"", "none", "nothing", "empty"})
_SPLIT = re.compile(r"[\s,;/()\[\]&+.:]+")


def normalize(text: str) -> str:
    """Lower case, spaces and dashes as underscores, trimmed."""
    return re.sub(r"[\s\-]+", "_", text.strip().lower())


def _singular(word: str) -> str:
    return word[:-1] if len(word) > 3 and word.endswith("s") and not word.endswith("ss") else word


@cache
def is_empty(contents: str) -> bool:
    """Whether a `contents` value means the container holds nothing."""
    return normalize(contents) in _EMPTY


@cache
def _traits(contents: str) -> frozenset[str] | None:
    key = normalize(contents)
    if key in _SUBSTANCES:
        return _SUBSTANCES[key]
    found: set[str] = set()
    recognised = False
    for word in _SPLIT.split(contents.lower()):
        for candidate in (word, _singular(word)):
            if candidate in _SUBSTANCES:
                found |= _SUBSTANCES[candidate]
                recognised = True
                break
    return frozenset(found) if recognised else None


@cache
def substance_trait(contents: str, trait: str) -> bool | None:
    """Whether the substance has a trait; False for empty contents; None if unrecognised.

    Args:
        contents: what a container holds, as free text.
        trait: one of `TRAITS`.

    Returns:
        True, False, or None when the substance is not in the table.
    """
    if is_empty(contents):
        return False
    traits = _traits(contents)
    return None if traits is None else trait in traits


# Foods that block a young child's airway when given whole (the paediatric choking lists:
# grapes, nuts, popcorn, hard sweets, cherry tomatoes, sausage rounds), and the preparations
# that make them safe to give, or turn them into something else (peanut butter, grape juice).
_BITE_SIZED = frozenset({"grape", "grapes", "nut", "nuts", "peanut", "peanuts", "almond",
                         "almonds", "cashew", "cashews", "hazelnut", "hazelnuts", "walnut",
                         "walnuts", "pistachio", "pistachios", "popcorn", "sweet", "sweets",
                         "candy", "candies", "lolly", "lollies", "gobstopper", "gobstoppers",
                         "marshmallow", "marshmallows", "cherry", "cherries", "olive", "olives",
                         "blueberry", "blueberries", "cherry_tomato", "cherry_tomatoes",
                         "sausage", "sausages", "hotdog", "hot_dog", "raisin", "raisins"})
_MADE_SAFE = frozenset({"halved", "quartered", "chopped", "mashed", "cut", "sliced", "pureed",
                        "puréed", "blended", "grated", "crushed", "ground", "butter", "juice",
                        "paste", "spread", "oil", "milk", "flour", "sauce", "soup", "puree"})


def bite_sized(text: str) -> bool:
    """Whether the text names a food a young child can choke on as given ("whole grapes",
    "peanuts"), not one cut up or made into something else ("halved grapes", "peanut butter")."""
    return _names_any(text, _BITE_SIZED) and not _words(text) & _MADE_SAFE


def _words(text: str) -> set[str]:
    return {w for w in _SPLIT.split(text.lower()) if w}


def _names_any(text: str, table: frozenset[str]) -> bool:
    """Whether the text names a member of the table, a word or a compound ("cherry_tomato")."""
    joined = normalize(text)
    return bool(_words(text) & table) or any(t in joined for t in table if "_" in t)


# What poisons a dog or a cat even in small amounts (veterinary poison-line lists).
_PET_POISONS = frozenset({"grape", "grapes", "raisin", "raisins", "sultana", "sultanas",
                          "currant", "currants", "chocolate", "cocoa", "onion", "onions",
                          "garlic", "leek", "leeks", "chives", "xylitol", "macadamia",
                          "macadamias", "avocado", "avocados", "coffee", "caffeine", "wine",
                          "beer", "alcohol", "whisky", "vodka", "ibuprofen", "paracetamol",
                          "aspirin", "lily", "lilies", "antifreeze", "slug_pellets"})


# Plants named only as plants: many (lilies, pothos, daffodils) poison cats, so the kind decides.
_UNNAMED_PLANTS = frozenset({"flower", "flowers", "bouquet", "posy", "plant", "plants",
                             "houseplant", "houseplants", "bulbs", "blooms"})


def pet_toxic(text: str) -> bool | None:
    """Whether the text names something that poisons a dog or a cat (grapes, chocolate, lilies);
    None for flowers or a plant of no named kind."""
    if _names_any(text, _PET_POISONS):
        return True
    return None if _words(text) & _UNNAMED_PLANTS else False


def same_substance(named: str, contents: str) -> bool:
    """Whether `contents` is, or contains, the substance `named` (or a member of its family)."""
    wanted = _singular(normalize(named))
    family = _FAMILIES.get(wanted, frozenset({wanted}))
    whole = normalize(contents)
    words = {_singular(w) for w in _SPLIT.split(contents.lower()) if w} | {whole, _singular(whole)}
    return bool(words & {_singular(f) for f in family} or whole in family)


def _drug_classes(text: str) -> set[str]:
    words = [_singular(w) for w in _SPLIT.split(text.lower()) if w]
    named = set(words) | {f"{a}_{b}" for a, b in pairwise(words)}
    named |= {normalize(text), _singular(normalize(text))}
    return {name for name, members in _DRUG_CLASSES.items() if named & members}


def alcoholic(text: str) -> bool:
    """Whether the text names an alcoholic drink ("red wine", "a beer", "whisky")."""
    return "alcohol" in _drug_classes(text) and not {"free", "alcohol-free", "non-alcoholic",
                                                       "zero"} & set(text.lower().split())


def interacts(substance: str, taken: str) -> bool:
    """Whether `substance` is dangerous for someone who takes `taken` (a medicine or drink)."""
    mine, theirs = _drug_classes(substance), _drug_classes(taken)
    return any(frozenset({a, b}) in _INTERACTING for a in mine for b in theirs)


def can_clash(substance: str) -> bool:
    """Whether the substance belongs to a class with some dangerous combination."""
    classes = _drug_classes(substance)
    return any(pair & classes for pair in _INTERACTING)
