"""Hand-written case descriptions, one module per domain x complexity cell of the grid."""
