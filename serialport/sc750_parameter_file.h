// Sc750ParameterFile: the SC750's set-up parameters as Motion Dialogue writes them — the PARAMS block at the
// top of a program (L943-L975) and the .PRM parameter set (DEFAULT.PRM, L2434-L2436). One reader and writer
// for Controller Set Up and Edit Parameters (app/families/sc750/sc750_setup_dialog) and servodesk-cli's vars dump/send.
//
// Format (the manual prints the block, L943-L975, but not the .PRM's layout; chosen: a .PRM is the block
// itself after ' comment lines, so it pastes into a program and Edit Parameters reads it back):
//   ' comment
//   PARAMS START
//   NAME = value      an integer parameter bare ("ILC = 59"), a real one with six decimals ("KVI = 5.000000")
//   PARAMS END
// Reading takes the first PARAMS block of a text (a whole .BAS program too) and nothing outside it; inside
// it, ' comments and blank lines are skipped, a value may be followed by a ' comment, and any other line is a
// problem reported at its line. Names and values are not checked here: the drive (or the compiler) does.
#pragma once

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <string>

namespace serialport {

struct Sc750ParameterAssignment {
    int sourceLine = 0; // 1-based line of the text
    QString name;       // upper case: "KVP"
    QString value;      // as written: "0.087086"
};

struct Sc750ParameterProblem {
    int sourceLine = 0;
    QString text;    // the line
    QString message; // "not an assignment (NAME = number)"
};

class Sc750ParameterFile {
public:
    static Sc750ParameterFile parse(const QString& text);

    // A parameter's value as the block shows it (the catalog says integer or real).
    static QString formatValue(const std::string& name, double value);
    // "PARAMS START", one "NAME = value" line each, "PARAMS END"; LF between, none after.
    static QString block(const QList<QPair<QString, QString>>& values);
    // text with its PARAMS block replaced by block, or with block (under Motion Dialogue's header comment)
    // put at the top when it has none.
    static QString withBlock(const QString& text, const QString& block);
    // "' comment" lines, then the block, LF line ends: a .PRM file.
    static QString toText(const QStringList& comments, const QList<QPair<QString, QString>>& values);

    bool hasBlock() const { return m_hasBlock; }
    const QList<Sc750ParameterAssignment>& assignments() const { return m_assignments; }
    const QList<Sc750ParameterProblem>& problems() const { return m_problems; }

private:
    bool m_hasBlock = false;
    QList<Sc750ParameterAssignment> m_assignments;
    QList<Sc750ParameterProblem> m_problems;
};

} // namespace serialport
