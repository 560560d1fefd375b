// A fluid's view as VTK frames (sim/frame_output.hpp): every field by its label, reals as
// Float32, a plane's vectors as (x, 0, z), integers as they are, a grid's cells beside.
#include <gtest/gtest.h>

#include <vector>

#include "sluice/sim/frame_output.hpp"

namespace sluice {
namespace {

TEST(FrameOf, ViewedFieldsKeepTheirNamesAndAPlanesVectorsGainY) {
  const std::vector<double> positions{0.5, 1.25, 2.0, 3.0};  // two points of a 2D case
  const std::vector<double> pressure{10.0, -2.5};
  const std::vector<std::int32_t> kind{0, 1};
  FluidView view;
  view.positions = FieldView::of("position", 2, positions.data(), 2);
  view.fields = {FieldView::of("pressure", 1, pressure.data(), 2),
                 FieldView::of("kind", kind.data(), 2),
                 FieldView::holding("velocity", 2, {1.0, 2.0, 3.0, 4.0})};
  const io::FluidFrame frame = frame_of(view);
  EXPECT_EQ(frame.points.points, (std::vector<float>{0.5f, 0, 1.25f, 2.0f, 0, 3.0f}));
  ASSERT_EQ(frame.points.float_arrays.size(), 2u);
  EXPECT_EQ(frame.points.float_arrays[0].name, "pressure");
  EXPECT_EQ(frame.points.float_arrays[0].components, 1);
  EXPECT_EQ(frame.points.float_arrays[0].values, (std::vector<float>{10.0f, -2.5f}));
  EXPECT_EQ(frame.points.float_arrays[1].name, "velocity");
  EXPECT_EQ(frame.points.float_arrays[1].components, 3);
  EXPECT_EQ(frame.points.float_arrays[1].values,
            (std::vector<float>{1.0f, 0, 2.0f, 3.0f, 0, 4.0f}));
  ASSERT_EQ(frame.points.int_arrays.size(), 1u);
  EXPECT_EQ(frame.points.int_arrays[0].name, "kind");
  EXPECT_EQ(frame.points.int_arrays[0].values, kind);
  EXPECT_EQ(frame.points.points_per_cell, 1);
  EXPECT_FALSE(frame.grid.has_value());
}

TEST(FrameOf, AViewOfSpaceKeepsItsVectorsAndItsCellsGoToTheGrid) {
  FluidView view;
  view.positions = FieldView::holding("position", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  view.points_per_cell = 3;  // one triangle
  FluidView::Cells cells;
  cells.count = {2, 1, 1};
  cells.origin = {-1, 0, 0.5};
  cells.spacing = 0.25;
  cells.fields = {FieldView::holding("level_set", 1, {-0.1, 0.3})};
  view.cells = cells;
  const io::FluidFrame frame = frame_of(view);
  EXPECT_EQ(frame.points.points, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(frame.points.points_per_cell, 3);
  ASSERT_TRUE(frame.grid.has_value());
  EXPECT_EQ(frame.grid->cells, (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(frame.grid->origin, (std::array<double, 3>{-1, 0, 0.5}));
  EXPECT_EQ(frame.grid->spacing, 0.25);
  ASSERT_EQ(frame.grid->cell_arrays.size(), 1u);
  EXPECT_EQ(frame.grid->cell_arrays[0].values, (std::vector<float>{-0.1f, 0.3f}));
}

TEST(FieldView, AHeldFieldSurvivesItsCopyAndAViewSeesItsArray) {
  std::vector<double> values{1, 2, 3};
  const FieldView viewed = FieldView::of("density", 1, values.data(), 3);
  values[1] = 7;  // a view reads the model's array as it is when read
  EXPECT_EQ(viewed.reals()[1], 7);
  EXPECT_EQ(viewed.elements(), 3u);
  FieldView copy = FieldView::holding("id", std::vector<std::int32_t>{4, 5});
  const FieldView held = copy;  // a copy holds its own values
  copy = FieldView::holding("other", 1, {});
  EXPECT_TRUE(held.is_integer());
  EXPECT_EQ(held.elements(), 2u);
  EXPECT_EQ(held.integers()[1], 5);
}

}  // namespace
}  // namespace sluice
