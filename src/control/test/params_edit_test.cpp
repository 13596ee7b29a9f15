// control::was_read (which keys a reader consumed) and control::replace (a deep copy of another
// tree's value, scalars still converting as written in YAML).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "control/params.hpp"
#include "control/params_edit.hpp"

namespace mechsim::control {
namespace {

TEST(ParamsEdit, WasReadTellsWhichKeysALookupReached) {
  Params p = Params::from_yaml_string("a: {b: 1, c: 2, d: 3}\nlist: [{x: 1}]\n");
  // child_or_create walks to an existing node without reading it.
  const Params a = p.child_or_create("a"), b = p.child_or_create("a/b"), c = p.child_or_create("a/c"),
               d = p.child_or_create("a/d");
  for (const Params& n : {a, b, c, d}) EXPECT_FALSE(was_read(n)) << n.path();
  EXPECT_EQ(p.get<int>("a/b"), 1);
  EXPECT_TRUE(was_read(a));
  EXPECT_TRUE(was_read(b));
  EXPECT_TRUE(p.has("a/c"));
  EXPECT_TRUE(was_read(c));
  EXPECT_FALSE(was_read(d));
  const Params item = p.child("list").items()[0];
  EXPECT_TRUE(was_read(item));
  const Params x = p.child("list").at(0).child_or_create("x");
  EXPECT_FALSE(was_read(x));
  EXPECT_EQ(item.get<int>("x"), 1);
  EXPECT_TRUE(was_read(x));
}

TEST(ParamsEdit, AnUnreadKeyStaysUnread) {
  Params tree = Params::from_yaml_string("w: {seed: 1}\n");
  const Params target = tree.child_or_create("w/sed");  // creating does not read
  replace(target, "", Params::from_yaml_string("v: 3").child("v"));
  EXPECT_FALSE(was_read(target));
  (void)tree.get<int>("w/seed");
  EXPECT_FALSE(was_read(target));
  EXPECT_TRUE(tree.has("w/sed"));
  EXPECT_TRUE(was_read(target));
}

TEST(ParamsEdit, ReplaceCopiesDeeplyAndPlainScalarsStillConvert) {
  Params into = Params::from_yaml_string("c: {pid: {p: 1.0, i: 2.0}, names: [a, b]}\n");
  const Params from = Params::from_yaml_string("p: 7\nlist: [3, 4.5]\nword: hello\n");
  replace(into, "c/pid/p", from.child("p"));
  replace(into, "c/names", from.child("list"));
  replace(into, "c/new/deep", from.child("word"));
  EXPECT_EQ(into.get<double>("c/pid/p"), 7.0);  // a plain "7": an integer that reads as a double
  EXPECT_EQ(into.get<int>("c/pid/p"), 7);
  EXPECT_EQ(into.get<double>("c/pid/i"), 2.0);
  EXPECT_EQ(into.get<std::vector<double>>("c/names"), (std::vector<double>{3.0, 4.5}));
  EXPECT_EQ(into.get<std::string>("c/new/deep"), "hello");
  // A copy, not a view: changing the source later leaves the target be.
  Params src = from;
  src.set("p", 9);
  EXPECT_EQ(into.get<int>("c/pid/p"), 7);
  // An empty key replaces the node itself: a list item; a value may be copied over its own parent.
  replace(into.child("c/names").at(1), "", from.child("word"));
  EXPECT_EQ(into.child("c/names").at(1).as<std::string>(), "hello");
  replace(into.child("c"), "", into.child("c/pid"));
  EXPECT_EQ(into.get<int>("c/p"), 7);
  // The copied nodes carry no line of the other file.
  EXPECT_EQ(into.child("c/p").location(), "");
}

}  // namespace
}  // namespace mechsim::control
