"""crossdiv's report: results.json (and bench.json) -> one section model -> report.md and index.html."""
