// Sc750SetupDialog: Options > Controller Set Up (L2430-L2610). Motor part number, the controller model
// read over the wire, Auto or Manual set-up and the System Response (Stiff/High Bandwidth or Gentle/Low
// Bandwidth, L2246). Auto computes the PARAMS values from the motor table (our rule, below); Manual shows
// the "Controller Set Up Data" (Sc750SetupDataTable, pre-filled from the motor), recomputes the values on
// every edit of it by the same rule, and lets the user edit the computed values too (L2530-L2553). OK writes the PARAMS
// block into the program in the editor, sends each value to the controller and configures it (K1). Non-modal; GUI
// thread only.
//
// chosen: the manual gives no formulas for the gains (digest §2.10). Both modes run
// catalog::sc750::setupParameters on a SetupData (Auto: the motor table's row, the boiler-plate motor for
// an unknown part); Gentle/Low Bandwidth halves KVP, KVI and KPP and lowers the anti-resonance filters to
// 100/500 Hz (large inertia mismatch, belts). The System Response choice serves both modes.
#pragma once

#include <QDialog>

class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QTableWidget;

namespace app {

class Sc750SetupDataTable;
class Sc750Workspace;

class Sc750SetupDialog final : public QDialog {
    Q_OBJECT
public:
    Sc750SetupDialog(Sc750Workspace& workspace, QWidget* parent = nullptr);

    // "PARAMS START" ... "PARAMS END" for the values in the table (serialport/sc750_parameter_file.h).
    QString paramsBlock() const;

    // File > Edit Parameters: Manual, with the values of text's PARAMS block where it has them.
    void loadParams(const QString& text);
    void setManual(bool manual);
    void setGentle(bool gentle);
    void setMotorPart(const QString& part);
    int controllerModel() const { return m_modelNumber; } // 0 until the controller has answered
    QTableWidget* table() const { return m_table; }       // the computed values
    Sc750SetupDataTable* setupDataTable() const { return m_data; }
    QString status() const;
    // OK: editor, controller, configure.
    void apply();

private:
    // Fills the computed values from the set-up data (Auto: the motor table's; Manual: the user's).
    void compute();
    void showMode();
    void setStatus(const QString& text, bool error);

    Sc750Workspace& m_workspace;
    QLineEdit* m_part;
    QLabel* m_model;
    QRadioButton* m_auto;
    QRadioButton* m_manual;
    QComboBox* m_response;
    QGroupBox* m_dataBox;
    Sc750SetupDataTable* m_data;
    QTableWidget* m_table;
    QLabel* m_status;
    QPushButton* m_ok = nullptr;
    int m_modelNumber = 0;
    bool m_fromProgram = false; // Edit Parameters: the values are the program's until the data are edited
};

} // namespace app
