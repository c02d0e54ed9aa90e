// The parameter panel edits the scene through the document: typed values, slider drags, vectors,
// choices and names each become one undo step, refused values show the declaration's reason and
// leave the scene alone, and undo, redo and removals elsewhere show up in the panel.
#include "document/SceneDocument.h"
#include "panels/BoolEditor.h"
#include "panels/ChoiceEditor.h"
#include "panels/IntEditor.h"
#include "panels/NumberField.h"
#include "panels/ParameterEditorFactory.h"
#include "panels/ParameterPanel.h"
#include "panels/RealEditor.h"
#include "panels/SliderScale.h"
#include "panels/StringEditor.h"
#include "panels/Vector3Editor.h"
#include "scene/ParameterCodec.h"
#include "scene/SceneSchema.h"
#include "support/WidgetTestMain.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTest>
#include <QUndoStack>
#include <memory>

namespace airtrap {

namespace {

const ParameterDeclaration& declarationOf(const std::string& section, const std::string& key) {
    return SceneSchema::findSection(section)->find(key)->declaration;
}

//! Replaces the widget's text the way a user does: select all, type, press Enter.
void typeInto(QWidget* widget, const QString& text) {
    if (auto* spinBox = qobject_cast<QAbstractSpinBox*>(widget))
        spinBox->selectAll();
    else if (auto* lineEdit = qobject_cast<QLineEdit*>(widget))
        lineEdit->selectAll();
    QTest::keyClicks(widget, text);
    QTest::keyClick(widget, Qt::Key_Return);
}

QPoint sliderHandleCentre(QSlider* slider) {
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    option.singleStep = slider->singleStep();
    option.pageStep = slider->pageStep();
    option.subControls = QStyle::SC_SliderGroove | QStyle::SC_SliderHandle;
    return slider->style()
        ->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider)
        .center();
}

} // namespace

class TestParameterPanel : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<SceneDocument> document_;
    std::unique_ptr<ParameterPanel> panel_;

    QUndoStack* undoStack() const { return document_->undoStack(); }
    const Scene& scene() const { return document_->scene(); }

    ParameterEditor* editor(const char* key) const {
        return panel_->findChild<ParameterEditor*>(QString::fromLatin1(key));
    }
    NumberField* field(const char* key) const {
        ParameterEditor* found = editor(key);
        return found ? found->findChild<NumberField*>(QStringLiteral("field")) : nullptr;
    }
    QLabel* errorLabel(const char* key) const {
        return panel_->findChild<QLabel*>(QStringLiteral("error_%1").arg(QLatin1String(key)));
    }

private Q_SLOTS:
    void init() {
        document_ = std::make_unique<SceneDocument>();
        document_->open(QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/dam_break.json"));
        panel_ = std::make_unique<ParameterPanel>(*document_);
        panel_->resize(700, 900);
        panel_->show();
        QVERIFY(QTest::qWaitForWindowExposed(panel_.get()));
    }

    void cleanup() {
        panel_.reset();
        document_.reset();
    }

    void everySectionGetsOneEditorPerDeclaredParameter() {
        for (const SchemaSection& section : SceneSchema::sections()) {
            // Every array section gets an element to show, whatever the sample holds.
            if (section.isArray && section.elementCount(document_->scene()) == 0)
                document_->addElement(section.key);
            panel_->showItem(section.isArray ? SceneItem::elementItem(section.key, 0)
                                             : SceneItem::sectionItem(section.key));
            const QList<ParameterEditor*> editors = panel_->findChildren<ParameterEditor*>();
            QCOMPARE(editors.size(), static_cast<qsizetype>(section.parameters.size()));
            for (const BoundParameter& parameter : section.parameters) {
                const ParameterDeclaration& declaration = parameter.declaration;
                ParameterEditor* found = editor(declaration.key.c_str());
                QVERIFY2(found, declaration.key.c_str());
                QCOMPARE(found->declaration().kind, declaration.kind);
                QVERIFY(found->toolTip().contains(QString::fromStdString(declaration.help)));
                auto* label = panel_->findChild<QLabel*>(
                    QStringLiteral("label_%1").arg(QString::fromStdString(declaration.key)));
                QVERIFY(label);
                QVERIFY(label->text().startsWith(QString::fromStdString(declaration.label)));
            }
        }
        panel_->showItem(SceneItem::sectionItem("solver"));
        auto* label = panel_->findChild<QLabel*>(QStringLiteral("label_particle_spacing"));
        QCOMPARE(label->text(), QStringLiteral("Particle spacing (m)"));
        const QString tip = editor("particle_spacing")->toolTip();
        QVERIFY2(tip.contains(QStringLiteral("[0.001, 1] m")), qPrintable(tip));
        QVERIFY2(tip.contains(QStringLiteral("Default: 0.02 m")), qPrintable(tip));
        QCOMPARE(panel_->findChild<QLabel*>(QStringLiteral("title"))->text(),
                 QStringLiteral("Solver"));
    }

    void factoryPicksTheWidgetForEachKind() {
        QWidget parent;
        const auto make = [&parent](ParameterKind kind) {
            ParameterDeclaration declaration{.key = "k", .label = "K", .kind = kind};
            return ParameterEditorFactory::create(declaration, &parent);
        };
        QVERIFY(qobject_cast<BoolEditor*>(make(ParameterKind::Bool)));
        QVERIFY(qobject_cast<IntEditor*>(make(ParameterKind::Int)));
        QVERIFY(qobject_cast<RealEditor*>(make(ParameterKind::Real)));
        QVERIFY(qobject_cast<Vector3Editor*>(make(ParameterKind::Vector3)));
        QVERIFY(qobject_cast<StringEditor*>(make(ParameterKind::String)));
        QVERIFY(qobject_cast<ChoiceEditor*>(make(ParameterKind::Choice)));
    }

    void boolEditorReportsClicksButNotSetValue() {
        BoolEditor checkEditor({.key = "flag", .label = "Flag", .kind = ParameterKind::Bool});
        std::vector<ParameterValue> edits;
        connect(&checkEditor, &ParameterEditor::edited,
                [&edits](const ParameterValue& value, bool) { edits.push_back(value); });
        checkEditor.setValue(true);
        QVERIFY(edits.empty());
        checkEditor.findChild<QCheckBox*>()->click();
        QCOMPARE(edits.size(), std::size_t{1});
        QCOMPARE(std::get<bool>(edits.front()), false);
    }

    void bubblesSectionSwitchesOnAsOneUndoStep() {
        panel_->showItem(SceneItem::sectionItem("bubbles"));
        QCOMPARE(panel_->findChild<QLabel*>(QStringLiteral("title"))->text(),
                 QStringLiteral("Bubbles"));
        auto* enabled = qobject_cast<BoolEditor*>(editor("enabled"));
        QVERIFY(enabled);
        QVERIFY(!scene().bubbles.enabled);
        auto* box = enabled->findChild<QCheckBox*>();
        QVERIFY(box);
        QVERIFY(!box->isChecked());

        box->click();
        QVERIFY(scene().bubbles.enabled);
        QCOMPARE(undoStack()->count(), 1);
        undoStack()->undo();
        QVERIFY(!scene().bubbles.enabled);
        QVERIFY(!box->isChecked());
        undoStack()->redo();
        QVERIFY(scene().bubbles.enabled);
        QVERIFY(box->isChecked());
    }

    void typedValueIsOneUndoStep() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        NumberField* spacing = field("particle_spacing");
        QVERIFY(spacing);
        QCOMPARE(spacing->text(), QStringLiteral("0.02"));

        typeInto(spacing, QStringLiteral("0.035"));
        QCOMPARE(scene().solver.particleSpacing, 0.035);
        QCOMPARE(undoStack()->count(), 1);
        QVERIFY(errorLabel("particle_spacing")->isHidden());

        undoStack()->undo();
        QCOMPARE(scene().solver.particleSpacing, 0.02);
        QCOMPARE(spacing->text(), QStringLiteral("0.02"));
        QCOMPARE(undoStack()->count(), 1);
        undoStack()->redo();
        QCOMPARE(spacing->text(), QStringLiteral("0.035"));
    }

    void stepArrowIsOneEdit() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        NumberField* spacing = field("particle_spacing");
        spacing->stepUp();
        QCOMPARE(scene().solver.particleSpacing, 0.021);
        QCOMPARE(spacing->text(), QStringLiteral("0.021"));
        QCOMPARE(undoStack()->count(), 1);
    }

    void outOfRangeValueIsRefusedWithReason_data() {
        QTest::addColumn<QString>("typed");
        QTest::newRow("above maximum") << QStringLiteral("5");
        QTest::newRow("negative") << QStringLiteral("-1");
        QTest::newRow("zero") << QStringLiteral("0");
    }

    void outOfRangeValueIsRefusedWithReason() {
        QFETCH(QString, typed);
        panel_->showItem(SceneItem::sectionItem("solver"));
        NumberField* spacing = field("particle_spacing");
        QLabel* error = errorLabel("particle_spacing");
        QVERIFY(error);
        QVERIFY(error->isHidden());

        typeInto(spacing, typed);
        QCOMPARE(scene().solver.particleSpacing, 0.02);
        QCOMPARE(undoStack()->count(), 0);
        QVERIFY(error->isVisible());
        const QString range = QString::fromStdString(
            ParameterCodec::rangeText(declarationOf("solver", "particle_spacing")));
        QVERIFY2(error->text().contains(range), qPrintable(error->text()));
        QCOMPARE(spacing->text(), QStringLiteral("0.02"));

        typeInto(spacing, QStringLiteral("0.03"));
        QVERIFY(error->isHidden());
        QCOMPARE(undoStack()->count(), 1);
    }

    void exclusiveMinimumIsRefused() {
        document_->addElement("obstacles");
        const int commands = undoStack()->count();
        panel_->showItem(SceneItem::elementItem("obstacles", 0));
        typeInto(editor("size")->findChild<NumberField*>(QStringLiteral("x")), QStringLiteral("0"));
        QCOMPARE(scene().obstacles[0].size.x(), 0.2);
        QCOMPARE(undoStack()->count(), commands);
        QVERIFY(errorLabel("size")->isVisible());
        QVERIFY2(errorLabel("size")->text().contains(QStringLiteral("(0, 1000]")),
                 qPrintable(errorLabel("size")->text()));
    }

    void sliderDragIsOneUndoStep() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        auto* slider = editor("particle_spacing")->findChild<QSlider*>(QStringLiteral("slider"));
        QVERIFY(slider);
        QVERIFY(slider->isVisible());
        const QPoint start = sliderHandleCentre(slider);
        QTest::mousePress(slider, Qt::LeftButton, Qt::NoModifier, start);
        QVERIFY(slider->isSliderDown());
        for (int step = 1; step <= 5; ++step)
            QTest::mouseMove(slider, start + QPoint(10 * step, 0));
        QTest::mouseRelease(slider, Qt::LeftButton, Qt::NoModifier, start + QPoint(50, 0));

        const double dragged = scene().solver.particleSpacing;
        QVERIFY2(dragged > 0.02, qPrintable(QString::number(dragged)));
        QCOMPARE(field("particle_spacing")->text(),
                 QString::fromStdString(ParameterCodec::formatNumber(dragged)));
        QCOMPARE(undoStack()->count(), 1);

        undoStack()->undo();
        QCOMPARE(scene().solver.particleSpacing, 0.02);
        QCOMPARE(field("particle_spacing")->text(), QStringLiteral("0.02"));
        const auto scale = SliderScale::forDeclaration(declarationOf("solver", "particle_spacing"));
        QCOMPARE(slider->value(), scale->positionOf(0.02));
    }

    void sliderValuesAreRoundAndWithinRange() {
        const ParameterDeclaration& spacing = declarationOf("solver", "particle_spacing");
        const std::optional<SliderScale> scale = SliderScale::forDeclaration(spacing);
        QVERIFY(scale);
        QVERIFY(scale->isLogarithmic());
        QCOMPARE(scale->valueAt(scale->firstPosition()), 0.001);
        QCOMPARE(scale->valueAt(scale->lastPosition()), 1.0);
        QCOMPARE(scale->valueAt(scale->positionOf(0.02)), 0.02);
        for (int position = scale->firstPosition(); position <= scale->lastPosition(); ++position) {
            const double value = scale->valueAt(position);
            QVERIFY(ParameterCodec::check(spacing, value, "spacing").empty());
            // Three significant digits, as a user would type them.
            QCOMPARE(QString::number(value, 'g', 3).toDouble(), value);
        }
        QVERIFY(!SliderScale::forDeclaration(declarationOf("", "seed")));
    }

    void vectorComponentEdit() {
        panel_->showItem(SceneItem::elementItem("fluid_blocks", 0));
        typeInto(editor("max")->findChild<NumberField*>(QStringLiteral("y")),
                 QStringLiteral("0.8"));
        QCOMPARE(scene().fluidBlocks[0].max, Vec3d(0.5, 0.8, 0.4));
        QCOMPARE(undoStack()->count(), 1);
        undoStack()->undo();
        QCOMPARE(scene().fluidBlocks[0].max, Vec3d(0.5, 1.0, 0.4));
        QCOMPARE(editor("max")->findChild<NumberField*>(QStringLiteral("y"))->text(),
                 QStringLiteral("1"));
    }

    void choiceListsDeclaredStrings() {
        document_->addElement("obstacles");
        panel_->showItem(SceneItem::elementItem("obstacles", 0));
        auto* combo = editor("shape")->findChild<QComboBox*>();
        QVERIFY(combo);
        const ParameterDeclaration& shape = declarationOf("obstacles", "shape");
        QCOMPARE(combo->count(), static_cast<int>(shape.choices.size()));
        QCOMPARE(combo->currentText(), QStringLiteral("box"));
    }

    void integerEditAndRefusal() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        NumberField* interval = field("shepard_interval");
        typeInto(interval, QStringLiteral("45"));
        QCOMPARE(scene().solver.shepardInterval, 45);
        typeInto(interval, QStringLiteral("-3"));
        QCOMPARE(scene().solver.shepardInterval, 45);
        QVERIFY(errorLabel("shepard_interval")->text().contains(QStringLiteral("[0, 10000]")));
        QCOMPARE(interval->text(), QStringLiteral("45"));
        QCOMPARE(undoStack()->count(), 1);
    }

    void nameEditRenamesElement() {
        panel_->showItem(SceneItem::elementItem("fluid_blocks", 0));
        auto* title = panel_->findChild<QLabel*>(QStringLiteral("title"));
        QCOMPARE(title->text(), QStringLiteral("Water column"));
        auto* name = editor("name")->findChild<QLineEdit*>();
        typeInto(name, QStringLiteral("Reservoir"));
        QCOMPARE(scene().fluidBlocks[0].name, std::string("Reservoir"));
        QCOMPARE(title->text(), QStringLiteral("Reservoir"));
        QCOMPARE(undoStack()->count(), 1);

        typeInto(name, QStringLiteral("   "));
        QCOMPARE(scene().fluidBlocks[0].name, std::string("Reservoir"));
        QCOMPARE(name->text(), QStringLiteral("Reservoir"));
        QVERIFY(errorLabel("name")->isVisible());
        QVERIFY(errorLabel("name")->text().contains(QStringLiteral("1 to 200 characters")));
        QCOMPARE(undoStack()->count(), 1);
    }

    void documentChangesUpdateWidgetsWithoutNewCommands() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        QVERIFY(
            document_->editParameter(SceneItem::sectionItem("solver"), "max_speed", 8.0).isEmpty());
        QCOMPARE(field("max_speed")->text(), QStringLiteral("8"));
        QCOMPARE(undoStack()->count(), 1);
        undoStack()->undo();
        QCOMPARE(field("max_speed")->text(), QStringLiteral("6"));
        undoStack()->redo();
        QCOMPARE(field("max_speed")->text(), QStringLiteral("8"));
        QCOMPARE(undoStack()->count(), 1);
        QCOMPARE(undoStack()->index(), 1);
    }

    void onlyTheFieldsOfTheChosenShapeAreShown() {
        const SceneItem body = document_->addElement("bodies");
        panel_->showItem(body);
        const auto shown = [this](const char* key) {
            return editor(key)->isVisibleTo(panel_.get());
        };
        // A box: its size; no radius, height or mesh.
        QVERIFY(shown("size") && shown("density") && shown("position"));
        QVERIFY(!shown("radius") && !shown("height") && !shown("mesh") && !shown("mesh_scale"));
        QVERIFY(
            !panel_->findChild<QLabel*>(QStringLiteral("label_radius"))->isVisibleTo(panel_.get()));
        document_->editParameter(body, "shape", std::string("cylinder"));
        QVERIFY(!shown("size") && shown("radius") && shown("height") && !shown("mesh"));
        document_->editParameter(body, "shape", std::string("mesh"));
        QVERIFY(!shown("radius") && shown("mesh") && shown("mesh_scale"));
        undoStack()->undo(); // back to the cylinder
        QVERIFY(shown("radius") && shown("height") && !shown("mesh"));

        const SceneItem emitter = document_->addElement("emitters");
        panel_->showItem(emitter);
        QVERIFY(shown("radius") && !shown("width") && !shown("height"));
        document_->editParameter(emitter, "shape", std::string("rectangle"));
        QVERIFY(!shown("radius") && shown("width") && shown("height"));
    }

    void resetRestoresDefault() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        auto* reset = panel_->findChild<QAction*>(QStringLiteral("reset_max_speed"));
        QVERIFY(reset);
        QVERIFY(reset->isEnabled());
        reset->trigger();
        QCOMPARE(scene().solver.maxSpeed, 10.0);
        QCOMPARE(field("max_speed")->text(), QStringLiteral("10"));
        QVERIFY(!reset->isEnabled());
        QCOMPARE(undoStack()->count(), 1);
    }

    void followsInsertedAndRemovedElements() {
        panel_->showItem(SceneItem::group("fluid_blocks"));
        auto* subtitle = panel_->findChild<QLabel*>(QStringLiteral("subtitle"));
        QVERIFY2(subtitle->text().contains(QStringLiteral("1 fluid block.")),
                 qPrintable(subtitle->text()));
        QVERIFY(panel_->findChildren<ParameterEditor*>().isEmpty());
        document_->addElement("fluid_blocks");
        QVERIFY(subtitle->text().contains(QStringLiteral("2 fluid blocks.")));

        panel_->showItem(SceneItem::elementItem("fluid_blocks", 1));
        document_->removeElement(SceneItem::elementItem("fluid_blocks", 0));
        QCOMPARE(panel_->item(), SceneItem::elementItem("fluid_blocks", 0));
        QCOMPARE(editor("name")->findChild<QLineEdit*>()->text(), QStringLiteral("Water"));

        document_->removeElement(SceneItem::elementItem("fluid_blocks", 0));
        QVERIFY(panel_->item().isNone());
        QVERIFY(panel_->findChildren<ParameterEditor*>().isEmpty());
    }

    void reopeningReloadsValues() {
        panel_->showItem(SceneItem::sectionItem("solver"));
        typeInto(field("max_speed"), QStringLiteral("7"));
        QCOMPARE(scene().solver.maxSpeed, 7.0);
        document_->open(QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/dam_break.json"));
        QCOMPARE(panel_->item(), SceneItem::sectionItem("solver"));
        QCOMPARE(field("max_speed")->text(), QStringLiteral("6"));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestParameterPanel)
#include "TestParameterPanel.moc"
