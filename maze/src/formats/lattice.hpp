#pragma once
// Lattices along one axis for the XML reader (xml_format.cpp): lengths that divide offsets,
// the lattice that puts points on cell centres, and the one two lattices share. Lengths in
// metres; `tol` is how far (m) a value may sit from a lattice line and still be on it.

#include <optional>
#include <vector>

namespace maze::lattice {

// The largest length dividing both a and b (>= 0) to within tol: Euclid on remainders, a
// remainder within tol of 0 or of the divisor counting as none. 0 when both are 0.
double common_divisor(double a, double b, double tol);

// Whether offset is a whole number of cells (to within tol).
bool on_lattice(double offset, double cell, double tol);

// The coarsest cell that puts every point (its offsets from the origin, along x and y) on a
// cell centre: a centre sits an odd number of half cells from the origin, so the cell is the
// largest length dividing every doubled offset, when each is an odd multiple of it. Nothing
// when there is no offset, one is on or before the origin, the doubled offsets are not all
// odd multiples of one length, the cell is no wider than `finest`, or more than kMaxMazeSide
// of them span `span`.
std::optional<double> centres_lattice(const std::vector<double> &offsets, double finest, double span, double tol);

// The coarsest cell that keeps the centres of centres_cell (centres_cell / m, m odd) and
// divides walls_cell into whole cells: the smallest such odd m. Nothing when the cell would
// be no wider than `finest` or more than kMaxMazeSide of them would span `span`.
std::optional<double> shared_lattice(double centres_cell, double walls_cell, double finest, double span,
                                     double tol);

}  // namespace maze::lattice
