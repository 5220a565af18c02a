// A VTK image read done only in a child process (importers/volume/image_read_in_child.h): the
// voxels, geometry and scalar type come back exactly; a refusal comes back as the child's
// sentence; a child that crashes, or writes past its buffers and then dies, is a refusal too, and
// this process never ran the reader.
#include "importers/volume/image_read_in_child.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <vtkPointData.h>
#include <vtkUnsignedShortArray.h>

#include <cstdint>

#include "core/error.h"
#include "importers/volume/volume_reader.h"
#include "tests/support/test_paths.h"

namespace viscera::importers::detail {
namespace {

/// `work`'s InputError message, or "no error".
template <typename Work>
std::string refusal(Work&& work) {
  try {
    work();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ImageReadInChild, the_image_comes_back_exactly) {
  const auto read = read_image_in_child(
      [] {
        // Made in the child: the parent never saw this image.
        vtkImageData* image = vtkImageData::New();
        image->SetDimensions(5, 4, 3);
        image->SetSpacing(0.5, 0.25, 2.0);
        image->SetOrigin(-1.0, 2.0, 30.0);
        image->AllocateScalars(VTK_UNSIGNED_SHORT, 2);
        auto* values = static_cast<std::uint16_t*>(image->GetScalarPointer());
        for (int i = 0; i < 5 * 4 * 3 * 2; ++i)
          values[i] = static_cast<std::uint16_t>(1000 + 7 * i);
        return image;  // the child exits without freeing it
      },
      "made.mha", "the test's reader");
  int dims[3];
  read->GetDimensions(dims);
  EXPECT_EQ(dims[0], 5);
  EXPECT_EQ(dims[1], 4);
  EXPECT_EQ(dims[2], 3);
  EXPECT_DOUBLE_EQ(read->GetSpacing()[1], 0.25);
  EXPECT_DOUBLE_EQ(read->GetOrigin()[2], 30.0);
  vtkDataArray* scalars = read->GetPointData()->GetScalars();
  ASSERT_NE(scalars, nullptr);
  EXPECT_EQ(scalars->GetDataType(), VTK_UNSIGNED_SHORT);
  EXPECT_EQ(scalars->GetNumberOfComponents(), 2);
  ASSERT_EQ(scalars->GetNumberOfValues(), 120);
  for (int i = 0; i < 120; ++i)
    ASSERT_EQ(scalars->GetComponent(i / 2, i % 2), 1000 + 7 * i) << i;
}

TEST(ImageReadInChild, a_refusal_in_the_child_comes_back_as_its_sentence) {
  const std::string message = refusal([] {
    read_image_in_child(
        []() -> vtkImageData* { throw core::InputError("ElementType required and not defined"); },
        "bad.mha", "the test's reader");
  });
  EXPECT_NE(message.find("bad.mha"), std::string::npos) << message;
  EXPECT_NE(message.find("ElementType required and not defined"), std::string::npos) << message;
}

TEST(ImageReadInChild, a_child_that_crashes_or_returns_nothing_is_a_refusal) {
  const std::string crashed = refusal([] {
    read_image_in_child(
        []() -> vtkImageData* {
          ::raise(SIGSEGV);
          return nullptr;
        },
        "crash.mha", "the test's reader");
  });
  EXPECT_NE(crashed.find("the test's reader crashes, hangs or exhausts its memory on it"),
            std::string::npos)
      << crashed;
  const std::string empty = refusal([] {
    read_image_in_child([]() -> vtkImageData* { return nullptr; }, "empty.mha", "the reader");
  });
  EXPECT_NE(empty.find("produced no voxels"), std::string::npos) << empty;
}

TEST(ImageReadInChild, the_nifti_finding_takes_no_more_memory_than_its_header_declares) {
  if (!core::guard_limits_memory()) GTEST_SKIP() << "sanitizer build: guards do not limit memory";
  // 384 bytes whose header made VTK's reader take 4.4 GB (8.6 GB for its siblings) for 10 s.
  const auto path = testing::source_dir() /
                    "tests/fuzz/regressions/volume_nifti/gigabytes_for_a_384_byte_header.nii";
  try {
    (void)read_volume(path);
  } catch (const core::InputError&) {  // refused or read: either way, within bounds
  }
  rusage children{}, self{};
  ::getrusage(RUSAGE_CHILDREN, &children);  // the largest child this process waited for
  ::getrusage(RUSAGE_SELF, &self);
  EXPECT_LT(children.ru_maxrss, 2L << 20) << "KB in a guard's child";
  EXPECT_LT(self.ru_maxrss, 2L << 20) << "KB in this process";
}

}  // namespace
}  // namespace viscera::importers::detail
