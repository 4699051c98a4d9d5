"""The condition language: grammar, AST, static checks, substitution, rendering, evaluation.

In: condition text from templates and contracts. Out: a checked, immutable `Formula`; canonical
text (`render`); a compiled three-valued evaluator (`compile_formula`). Every failure to parse or
type-check is a `FormulaError` with line and column. The Z3 encoder lives in `app.domain.smt`.
"""

from app.domain.errors import FormulaError
from app.domain.formula.checker import accepts, check, comparable, infer_type
from app.domain.formula.evaluator import CompiledFormula, compile_formula
from app.domain.formula.facts import (
    ActionArgs,
    Facts,
    FactValue,
    Unknown,
    Value,
    fact_key,
)
from app.domain.formula.nodes import (
    ROBOT_ID,
    ActionArg,
    Apply,
    Arith,
    BoolConst,
    BoundVar,
    Compare,
    EntityRef,
    Formula,
    Logic,
    Neg,
    Not,
    NumberLit,
    Quantifier,
    RobotConst,
    StringLit,
    VarRef,
)
from app.domain.formula.parser import parse
from app.domain.formula.render import render
from app.domain.formula.symbolic import SymbolicFacts, symbolic_bindings
from app.domain.formula.table import TableFacts
from app.domain.formula.transform import (
    entity_variables,
    substitute,
    symbols_used,
    uses_action_args,
    variables_used,
)
from app.domain.formula.vocabulary import ACTION_ARGUMENTS, VOCABULARY, Symbol

__all__ = [
    "ACTION_ARGUMENTS",
    "ROBOT_ID",
    "VOCABULARY",
    "ActionArg",
    "ActionArgs",
    "Apply",
    "Arith",
    "BoolConst",
    "BoundVar",
    "Compare",
    "CompiledFormula",
    "EntityRef",
    "FactValue",
    "Facts",
    "Formula",
    "FormulaError",
    "Logic",
    "Neg",
    "Not",
    "NumberLit",
    "Quantifier",
    "RobotConst",
    "StringLit",
    "Symbol",
    "SymbolicFacts",
    "TableFacts",
    "Unknown",
    "Value",
    "VarRef",
    "accepts",
    "check",
    "comparable",
    "compile_formula",
    "entity_variables",
    "fact_key",
    "infer_type",
    "parse",
    "render",
    "substitute",
    "symbolic_bindings",
    "symbols_used",
    "uses_action_args",
    "variables_used",
]
