// The lengths, in block lengths, that tell a corner touching a face from
// one near it or inside it (docs/model.md section 17), shared by the files
// of BlockContacts.
#pragma once

namespace jl::block_contact {

// Of a block length: a corner this close to a face touches it (a located
// crossing lands far inside: the bracket is 1e-9 s wide), and a resting
// corner may overhang the face's end by as much before it slides off.
constexpr double kTouchBand = 1e-7;
// Of a block length: the rounding of a gap computed from poses (kept out
// of the event functions, as kAngleTolerance is for the fold angle).
constexpr double kRounding = 1e-12;
// Of a block length: a corner this far outside a face's plane stands
// clearly outside it (cornerAgainst); below it, two planes a corner lies on
// at once are told apart by the face it came through.
constexpr double kFlush = kTouchBand;
// Of a block length: a contact that parted reads its gap from where it
// parted until it is this far clear.
constexpr double kClear = 1e-6;
// A resting contact's share (docs/model.md section 17.2) at or below this is
// the rounding's: the pins hold its corner by themselves.
constexpr double kRedundant = 1e-12;
// m: the table top reaches this far either side of the ground's origin, so
// a corner never slides off it.
constexpr double kTableHalfLength = 1e6;

}  // namespace jl::block_contact
