"""The symbolic AI2-THOR-compatible household simulator and its end-to-end evaluation.

In: scenarios (`sim/scenarios/*.yaml`) on real iTHOR floor plans (`sim/data/`). Out: episodes run
gate -> contract -> plan -> verify -> execute under the runtime monitor, scored as CR% and TC%
(`python -m sim`, `make sim`). Modules: `floorplans` (AI2-THOR metadata -> scene objects),
`scenario` (the scenario files), `physics` (AI2-THOR's refusals and automatic effects), `hazards`
(the labelled hazard layer), `simulator`, `goals` and `planner` (the `Planner` protocol and the
search planner), `methods` (SafeGate and the baselines), `episode`, `runner`, `report`, and
`ai2thor_adapter` (the same action API over real AI2-THOR; optional, not exercised here).
"""
