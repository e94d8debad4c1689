"""Mutation testing of the references (make mutate): drawing and its rules, the plugin of a mutant's run,
what each test is made of, and the three kill rates."""
