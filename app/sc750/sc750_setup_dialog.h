// Sc750SetupDialog: Options > Controller Set Up (L2430-L2610). Motor part number, the controller model
// read over the wire, Auto or Manual set-up and the System Response (Stiff/High Bandwidth or Gentle/Low
// Bandwidth, L2246). Auto computes the PARAMS values (our rule, below); Manual lets the user edit them.
// OK writes the PARAMS block into the program in the editor, sends each value to the controller and
// configures it (K1). Non-modal; GUI thread only.
//
// chosen: the manual gives no formulas for the gains (digest §2.10). Auto takes the motor's and the
// controller model's values from drive_core's small motor table (catalog::sc750::setupParameters, the
// boiler-plate set for an unknown motor) and for Gentle/Low Bandwidth halves KVP, KVI and KPP and lowers
// the anti-resonance filters to 100/500 Hz (large inertia mismatch, belts).
#pragma once

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QTableWidget;

namespace app {

class Sc750Workspace;

class Sc750SetupDialog final : public QDialog {
    Q_OBJECT
public:
    Sc750SetupDialog(Sc750Workspace& workspace, QWidget* parent = nullptr);

    // The Auto values for a motor part number ("R45G...") on a controller MODEL (0 = unknown): name and
    // value of every PARAMS parameter, in catalog order.
    static QList<QPair<QString, double>> autoParameters(bool gentle, const QString& motorPart, int model);
    // "PARAMS START" ... "PARAMS END" for the values in the table.
    QString paramsBlock() const;
    // Replaces the PARAMS block of text (or puts one at the top) with block.
    static QString withParams(const QString& text, const QString& block);

    // File > Edit Parameters: Manual, with the values of text's PARAMS block where it has them.
    void loadParams(const QString& text);
    void setManual(bool manual);
    void setGentle(bool gentle);
    void setMotorPart(const QString& part);
    int controllerModel() const { return m_modelNumber; } // 0 until the controller has answered
    QTableWidget* table() const { return m_table; }
    QString status() const;
    // OK: editor, controller, configure.
    void apply();

private:
    void fillAuto();
    void setStatus(const QString& text, bool error);

    Sc750Workspace& m_workspace;
    QLineEdit* m_part;
    QLabel* m_model;
    QRadioButton* m_auto;
    QRadioButton* m_manual;
    QComboBox* m_response;
    QTableWidget* m_table;
    QLabel* m_status;
    int m_modelNumber = 0;
};

} // namespace app
