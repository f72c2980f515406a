// labels: io
// The benchmark report's templates: a placeholder without a value, or a value
// without a placeholder, is an error that names it; every built-in template
// is there and is well formed.
#include "bench/template.h"

#include <QtTest>

#include <regex>
#include <string>

using namespace jl::bench;

class ReportTemplateTest : public QObject {
    Q_OBJECT
private slots:
    void fillsEveryPlaceholder() {
        std::string error;
        const auto text = fillTemplate("a {{x}} b {{y}} c {{x}}", {{"x", "1"}, {"y", "2"}}, error);
        QVERIFY(text);
        QCOMPARE(*text, std::string("a 1 b 2 c 1"));
    }

    void aMissingValueIsNamed() {
        std::string error;
        QVERIFY(!fillTemplate("a {{x}} b {{y}}", {{"x", "1"}}, error));
        QVERIFY2(error.find("{{y}}") != std::string::npos, error.c_str());
    }

    void anUnusedValueIsNamed() {
        std::string error;
        QVERIFY(!fillTemplate("a {{x}}", {{"x", "1"}, {"z", "2"}}, error));
        QVERIFY2(error.find("{{z}}") != std::string::npos, error.c_str());
    }

    void anUnclosedPlaceholderIsAnError() {
        std::string error;
        QVERIFY(!fillTemplate("a {{x b", {{"x", "1"}}, error));
        QVERIFY(!error.empty());
    }

    // Each part of the report is built in, and fills once each of its names has a value.
    void everyBuiltInTemplateFills() {
        for (const char* part : {"performance", "stability", "stability_beyond", "stability_within", "models", "events",
                                 "examples", "folding"}) {
            const std::string text(reportTemplate(part));
            QVERIFY2(text.size() > 100, part);
            TemplateValues values;
            const std::regex name("\\{\\{([a-z0-9_]+)\\}\\}");
            for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != std::sregex_iterator(); ++it)
                values[(*it)[1]] = (*it)[1].str();
            std::string error;
            const auto filled = fillTemplate(text, values, error);
            QVERIFY2(filled, (std::string(part) + ": " + error).c_str());
            QVERIFY2(filled->find("{{") == std::string::npos, part);
        }
        QVERIFY(reportTemplate("no such part").empty());
    }
};

QTEST_APPLESS_MAIN(ReportTemplateTest)
#include "test_report_template.moc"
