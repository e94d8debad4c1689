"""The test outline as files: the registry and its checks, tags, Gherkin, requirement texts, new items, the
step catalogue and what each Then rests on."""
