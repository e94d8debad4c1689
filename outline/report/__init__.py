"""The reviewer's report: the Allure environment and metadata, the one-file HTML, its browser check and the
run's summary."""
