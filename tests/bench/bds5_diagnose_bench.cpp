// Benchmark: open + highlight + diagnose a 2,000-line BDS5 program in the editor (issue 5 goal: < 50 ms).
// Prints the time of each stage separately — loading the file, styling every line, checkProgram (the
// drive's front end), showing the diagnostics — as the median of several runs. Never asserts a time.
#include "editor/bds5_diagnostics.h"
#include "editor/bds5_language.h"
#include "editor/program_editor.h"

#include "drive_core/bds5/bds5_checker.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

constexpr int kLines = 2000;
constexpr int kRuns = 7;

// A program that looks like real ones: labelled routines with moves, waits, prints, IF blocks, quick IFs,
// assignments with expressions, comments — and one mistake per routine (`PROP 2`, an unknown word, a
// missing label) so the annotations have work to do.
QByteArray makeProgram(int lines, bool everyLineWrong) {
    QByteArray out;
    int n = 0, label = 1;
    auto add = [&](const QByteArray& line) {
        out += line + "\r\n";
        ++n;
    };
    add("; GENERATED 2,000-LINE BENCHMARK PROGRAM");
    add("POWER-UP$                ;POWER-UP LABEL");
    add("PLIM OFF");
    add("END");
    while (n < lines - 3) {
        if (everyLineWrong) {
            add("PROP 2");
            continue;
        }
        add(QByteArray::number(label) + "$                ;ROUTINE " + QByteArray::number(label));
        add("  X1=X1+1 ;COUNT CYCLES");
        add("  ACC=10000");
        add("  DEC=ACC");
        add("  MA 4000*X2/100 1000");
        add("  W 0");
        add("  IF X1 GT 100");
        add("    P \"LIMIT REACHED\" X1[6]");
        add("    X1=0");
        add("  ELIF X1 LT 0");
        add("    X1=(X1+1)*2");
        add("  ELSE");
        add("    D 250");
        add("  ENDIF");
        add("  ? I1 EQ ON GOSUB " + QByteArray::number(label));
        add("  TIL PFB GE 4000");
        add(label % 3 == 0 ? "  PROP 2" : (label % 3 == 1 ? "  FOOBAR 1" : "  GOTO 499"));
        add("  RET");
        ++label;
    }
    add("ERROR$");
    add("P \"ERROR\" LSTERR");
    add("B");
    return out;
}

double medianMs(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Figures {
    double open, highlight, check, show;
    std::size_t diagnostics;
};

Figures measure(const QString& path) {
    std::vector<double> open, highlight, check, show;
    std::size_t count = 0;
    for (int run = 0; run < kRuns; ++run) {
        editor::ProgramEditor ed;
        editor::Bds5Language* bds5 = editor::Bds5Language::install(ed);
        ed.resize(1000, 800);
        QElapsedTimer t;
        t.start();
        ed.loadFile(path);
        open.push_back(t.nsecsElapsed() / 1e6);
        t.restart();
        ed.SendScintilla(QsciScintilla::SCI_COLOURISE, 0, -1); // every line, not just the visible ones
        highlight.push_back(t.nsecsElapsed() / 1e6);
        t.restart();
        auto diagnostics = drive_core::bds5::checkProgram(editor::Bds5Diagnostics::programLines(ed.text()));
        check.push_back(t.nsecsElapsed() / 1e6);
        count = diagnostics.size();
        t.restart();
        bds5->diagnostics()->show(std::move(diagnostics));
        show.push_back(t.nsecsElapsed() / 1e6);
    }
    return {medianMs(open), medianMs(highlight), medianMs(check), medianMs(show), count};
}

void print(const char* title, const Figures& f) {
    const double total = f.open + f.highlight + f.check + f.show;
    std::printf("%s\n", title);
    std::printf("  open (load file into editor)     %7.2f ms\n", f.open);
    std::printf("  highlight (style all %d lines) %7.2f ms\n", kLines, f.highlight);
    std::printf("  checkProgram (drive front end)   %7.2f ms\n", f.check);
    std::printf("  show %5zu diagnostics           %7.2f ms\n", f.diagnostics, f.show);
    std::printf("  total                            %7.2f ms   (goal < 50 ms: %.2f of the goal)\n", total,
                total / 50.0);
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QTemporaryDir dir;
    const QString typical = dir.filePath(QStringLiteral("typical.bds"));
    const QString wrong = dir.filePath(QStringLiteral("wrong.bds"));
    for (const auto& [path, bytes] :
         {std::pair{typical, makeProgram(kLines, false)}, std::pair{wrong, makeProgram(kLines, true)}}) {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size()) return 1;
    }
    std::printf("BDS5 open + highlight + diagnose, %d lines, median of %d runs\n", kLines, kRuns);
    print("typical program (an error every 18 lines):", measure(typical));
    print("worst case (every line an error):", measure(wrong));
    return 0;
}
