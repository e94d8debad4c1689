"""The system under test, reached only through `sut.driver.TrainDriver`.

Backends are registered by name in `sut.backends`; `reference` is the embedded simulation.
"""
