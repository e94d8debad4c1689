// Allure 3 configuration, read by `npx allure generate` from the repository root (see `make report`).
export default {
  name: "Train network conformance: CRH2, metro TCN, ATP",
  output: "./reports/html",
  // Kept between `make report` runs (make clean removes it): the report shows each test's recent history.
  historyPath: "./reports/history.jsonl",
  plugins: {
    awesome: {
      options: {
        reportName: "Train network conformance: CRH2, metro TCN, ATP",
        // One self-contained index.html: opened from disk (file://) it cannot fetch separate data files.
        singleFile: true,
        // Tree = test outline: class -> category -> item (labels set by outline/plugin/pytest_plugin.py).
        groupBy: ["epic", "feature", "story"],
      },
    },
  },
};
