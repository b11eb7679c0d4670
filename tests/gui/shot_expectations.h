// unmetExpectations: a screenshot's own content checked against what its shot should show — the checks of
// one screenshot_check SPEC (text=, dock=, title=, plot; see screenshot_check.cpp) against the shot's facts
// (the tour's "<name>.png.facts", see app/tour/shot_facts.h) and its pixels.
#pragma once

#include <QImage>
#include <QStringList>

// One message per check that fails (an unknown check fails too); empty when all hold. image: ARGB32.
QStringList unmetExpectations(const QStringList& checks, const QStringList& facts, const QImage& image);
