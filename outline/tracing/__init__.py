"""Traceability: requirement -> items -> scenarios, from the registry or a run's results, rendered as
Markdown, HTML and an Allure entry."""
