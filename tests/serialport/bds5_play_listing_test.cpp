// Bds5PlayListing on hand-made damage: copies that agree give the listing; lines run together, a lost
// header or a stray prompt before the echo never shift samples; a recording set up differently is named.
#include "serialport/bds5_play_listing.h"

#include <gtest/gtest.h>

using serialport::Bds5PlayListing;

namespace {

const QString kHeader = QStringLiteral("RECORD 4 1 VCMD VFB");

QString field(int value) {
    return QString::number(value).rightJustified(12);
}

QStringList truth() {
    return {kHeader, field(0) + field(0), field(1000) + field(12), field(1000) + field(340), field(0) + field(-77)};
}

QString listing(QStringList lines) {
    return lines.join(QStringLiteral("\r\n")) + QStringLiteral("\r\n");
}

} // namespace

TEST(Bds5PlayListing, twoCleanCopiesAreEnough) {
    Bds5PlayListing l(kHeader, 4, 2);
    l.addCopy(listing(truth()), false);
    EXPECT_FALSE(l.complete());
    l.addCopy(listing(truth()), false);
    ASSERT_TRUE(l.complete());
    EXPECT_EQ(l.lines(), truth());
}

TEST(Bds5PlayListing, onATrustedLinkOneCleanCopyIsEnough) {
    Bds5PlayListing l(kHeader, 4, 2);
    l.setTrustCleanCopy(true);
    l.addCopy(listing(truth()), false);
    ASSERT_TRUE(l.complete());
    EXPECT_EQ(l.lines(), truth());
}

TEST(Bds5PlayListing, aDamagedCopyEndsTheTrust) {
    Bds5PlayListing l(kHeader, 4, 2);
    l.setTrustCleanCopy(true);
    QStringList shortened = truth();
    shortened[2].remove(3, 1);
    l.addCopy(listing(shortened), false);
    l.addCopy(listing(truth()), false);
    EXPECT_FALSE(l.complete()); // one clean copy no longer decides
    l.addCopy(listing(truth()), false);
    ASSERT_TRUE(l.complete());
    EXPECT_EQ(l.lines(), truth());
}

TEST(Bds5PlayListing, linesRunTogetherKeepTheLinesAfterThemInPlace) {
    Bds5PlayListing l(kHeader, 4, 2);
    QStringList merged = truth();
    merged[1] += QStringLiteral("\n") + merged[2]; // the CR of line 1 was lost
    merged.removeAt(2);
    for (int i = 0; i < 3; ++i) l.addCopy(listing(merged), false);
    EXPECT_EQ(l.samplesAgreed(), 3); // the first line of the stretch still reads; the second cannot
    EXPECT_FALSE(l.complete());
    l.addCopy(listing(truth()), false);
    EXPECT_FALSE(l.complete()); // sample 2 has one reading only
    l.addCopy(listing(truth()), false);
    l.addCopy(listing(truth()), false);
    ASSERT_TRUE(l.complete());
    EXPECT_EQ(l.lines(), truth());
}

TEST(Bds5PlayListing, aDroppedByteNeverShiftsAValueIntoTheNextColumn) {
    Bds5PlayListing l(kHeader, 4, 2);
    QStringList shortened = truth();
    shortened[2].remove(3, 1); // "   1000" loses a blank: the VFB column now starts one character early
    for (int i = 0; i < 5; ++i) l.addCopy(listing(shortened), true);
    EXPECT_EQ(l.samplesAgreed(), 3);
    EXPECT_FALSE(l.complete());
}

TEST(Bds5PlayListing, twoDamagedCopiesThatAgreeAreNotEnough) {
    Bds5PlayListing l(kHeader, 4, 2);
    QStringList flipped = truth();
    flipped[3].replace(QStringLiteral("340"), QStringLiteral("341")); // one bit flipped, the same twice
    l.addCopy(listing(flipped), true);
    l.addCopy(listing(flipped), true);
    l.addCopy(listing(truth()), true);
    EXPECT_FALSE(l.complete());
    l.addCopy(listing(truth()), true);
    l.addCopy(listing(truth()), true);
    l.addCopy(listing(truth()), true);
    l.addCopy(listing(truth()), true);
    ASSERT_TRUE(l.complete()); // 5 against 2
    EXPECT_EQ(l.lines(), truth());
}

TEST(Bds5PlayListing, aStrayPromptBeforeTheEchoIsSkipped) {
    Bds5PlayListing l(kHeader, 4, 2);
    for (int i = 0; i < 3; ++i) l.addCopy(QStringLiteral("-->PLAY\r\n") + listing(truth()), true);
    ASSERT_TRUE(l.complete());
    EXPECT_EQ(l.lines(), truth());
}

TEST(Bds5PlayListing, aCopyWithoutItsHeaderLineIsNotPlaced) {
    Bds5PlayListing l(kHeader, 4, 2);
    QStringList noHeader = truth();
    noHeader.removeFirst(); // its line end lost: "RECORD ...   0   0" would not anchor either
    for (int i = 0; i < 5; ++i) l.addCopy(listing(noHeader), false);
    EXPECT_EQ(l.samplesAgreed(), 0);
}

TEST(Bds5PlayListing, aRecordingSetUpDifferentlyIsNamedAndNeverAccepted) {
    Bds5PlayListing l(kHeader, 4, 2);
    QStringList other = truth();
    other[0] = QStringLiteral("RECORD 4 3 VCMD VFB"); // RECORD 4 1 damaged on its way: 3 ms, not 1 ms
    l.addCopy(listing(other), false);
    l.addCopy(listing(other), false);
    EXPECT_FALSE(l.complete());
    EXPECT_FALSE(l.otherHeader());
    l.addCopy(listing(other), false);
    EXPECT_FALSE(l.complete());
    ASSERT_TRUE(l.otherHeader());
    EXPECT_EQ(*l.otherHeader(), other[0]);
}
