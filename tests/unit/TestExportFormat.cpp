// The export formats and up axes are named in one place (io/ExportFormat.h, core/UpAxis.h); the
// command line, the editor's log and the messages read the names from there.
#include "core/Error.h"
#include "io/SequenceExporter.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;

class TestExportFormat : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyFormatIsFoundByItsName() {
        for (ExportFormat format : kExportFormats)
            QCOMPARE(exportFormatNamed(exportFormatName(format)), std::optional(format));
        QCOMPARE(exportFormatName(ExportFormat::Vdb), std::string_view("vdb"));
        QVERIFY(!exportFormatNamed("fbx"));
        QVERIFY(!exportFormatNamed("OBJ"));
        QCOMPARE(exportFormatList(), std::string("obj, vdb or ply"));
    }

    void anUnknownFormatIsRefusedWithTheList() {
        QCOMPARE(SequenceExporter::parseFormat("ply"), ExportFormat::Ply);
        try {
            SequenceExporter::parseFormat("fbx");
            QFAIL("fbx accepted");
        } catch (const Error& error) {
            QCOMPARE(error.kind(), ErrorKind::InvalidInput);
            QVERIFY2(std::string(error.what()).find("expected obj, vdb or ply") !=
                         std::string::npos,
                     error.what());
        }
    }

    void upAxesAreFoundByTheirNames() {
        QCOMPARE(upAxisNamed("y"), std::optional(UpAxis::Y));
        QCOMPARE(upAxisNamed("z"), std::optional(UpAxis::Z));
        QCOMPARE(upAxisName(UpAxis::Z), std::string_view("z"));
        QVERIFY(!upAxisNamed("x"));
    }
};

AIRTRAP_TEST_APPLESS(TestExportFormat)
#include "TestExportFormat.moc"
