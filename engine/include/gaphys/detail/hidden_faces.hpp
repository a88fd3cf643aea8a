// Contacts on faces that another static shape hides: the seams of a floor
// of static boxes laid flush (docs/engine.md, "Seams").
//
// A body sliding over such a floor rests a fraction of a millimetre into
// one box, and meets the next one's side face, which the first box covers:
// the narrow phase, seeing only that pair, finds the side the deepest
// separating axis and makes a (speculative) contact along it, which stops
// the body or throws it up ("ghost collisions"; a frictionless box at 3 m/s
// kept 1.06 m/s after the first seam, hopping). Such a contact is dropped
// where the face it lies on is hidden there by another static shape that
// the same body touches in this step.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "gaphys/algebra.hpp"
#include "gaphys/contact.hpp"

namespace gaphys::detail {

// Whether the contact point on static shape `s` (its surface point `p`, its
// outward normal `n` there) lies on a face that static shape `other` hides:
// just in front of the face (p + δ n) `other` is there, within `slop` of its
// surface; `s` ends where the surface of `other` is (from p, δ along that
// surface's normal is outside `s` by δ / 2 or more); and the two are flush
// (along that normal, `s` ends where the other's surface is, within the
// slop). δ is four times the slop: a body resting up to the slop into the
// first box of a seam is hidden from the second's side; a wall standing on
// a floor, whose face goes on above the floor, keeps its contacts there, as
// does a step or a plate thicker than the slop. At an edge or corner of a
// box or hull, the faces through p that n leans towards are tested (a ball
// rolling over a seam meets the next box's edge).
bool hidden_by(const placed_shape& s, const vector& p, const vector& n, const placed_shape& other,
               real slop);

// A contact between a static body and another, as the narrow phase makes
// it: its place in the contact list, the other (moving) body, and the
// static shape's place among the placed shapes. (What drop_hidden_contacts
// reads of every such contact: read from the contacts, 248 bytes each and
// just written on any thread, they took 0.1 ms of a 10,000-sphere step.)
struct static_contact {
  std::size_t contact;
  std::size_t moving;
  std::size_t shape;
};

// drop_hidden_contacts' lists, kept from step to step so as not to be
// allocated anew (first_partner is all zero between calls).
struct hidden_face_lists {
  std::vector<std::size_t> first_partner;  // per body: its first static shape + 1, or `several`
  std::vector<std::size_t> touched;        // the bodies whose first_partner is set
  std::vector<std::pair<std::size_t, std::size_t>> entries;  // (moving body, contact)
  std::vector<unsigned char> dropped;                        // per contact
  // One body's static shapes: their bounds (by the lowest x), and those
  // every contact point looks at (planes, and shapes far wider than most).
  struct partner {
    struct corner {
      real x, y, z;
    } lo, hi;
    std::size_t shape;
  };
  std::vector<partner> partners;
  std::vector<std::size_t> everywhere;
  std::vector<real> widths;
};

// Drops, keeping the others' order, each contact between a static shape and
// a body that is not static whose point lies on a face hidden (hidden_by) by
// another static shape the same body has a contact with; never one deeper
// than twice the slop. `placed` holds every shape of the contacts' bodies at
// its pose, body i's from first_shape[i]; `is_static` says which bodies are
// static; on_static[0 .. static_count) lists, in order, the contacts
// between a static body and another (only those are read).
void drop_hidden_contacts(const placed_shape* placed, const std::size_t* first_shape,
                          const std::vector<unsigned char>& is_static, real slop,
                          const static_contact* on_static, std::size_t static_count,
                          std::vector<contact>& contacts, hidden_face_lists& lists);

}  // namespace gaphys::detail
