// AlgorithmService over loopback: every registered planner with its schema.
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

TEST(AlgorithmsTest, ListAlgorithmsReturnsEveryRegisteredPlannerWithItsSchema) {
  TempDir dir;
  TestServer server(dir.path());
  v1::ListAlgorithmsResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(server.algorithms().ListAlgorithms(&context, {}, &response).ok());
  ASSERT_EQ(response.algorithms_size(), static_cast<int>(TestRegistry().planners().size()));
  for (int i = 0; i < response.algorithms_size(); ++i) {
    const v1::Algorithm& a = response.algorithms(i);
    const PlannerInfo& info = TestRegistry().planners()[i];
    EXPECT_EQ(a.id(), info.id);
    EXPECT_EQ(a.description(), info.description);
    EXPECT_EQ(a.map_kinds_size(), static_cast<int>(info.map_kinds.size()));
    EXPECT_EQ(a.parameters_size(), static_cast<int>(info.params.size()));
    EXPECT_FALSE(a.encoding().empty());
  }
  const v1::Algorithm& slow = response.algorithms(response.algorithms_size() - 1);
  ASSERT_EQ(slow.id(), "test-slow");
  const v1::ParameterSpec& iterations = slow.parameters(0);
  EXPECT_EQ(iterations.name(), "iterations");
  EXPECT_EQ(iterations.type(), v1::PARAMETER_TYPE_INT);
  EXPECT_EQ(iterations.default_value().int_value(), 10);
  EXPECT_EQ(iterations.min(), 1);
  EXPECT_EQ(iterations.max(), 1000000);
  EXPECT_EQ(iterations.unit(), "iterations");
}

TEST(AlgorithmsTest, GetAlgorithmByIdAndUnknownIdListsTheValidOnes) {
  TempDir dir;
  TestServer server(dir.path());
  v1::GetAlgorithmRequest request;
  request.set_id("test-slow");
  v1::Algorithm algorithm;
  grpc::ClientContext c1, c2;
  ASSERT_TRUE(server.algorithms().GetAlgorithm(&c1, request, &algorithm).ok());
  EXPECT_EQ(algorithm.id(), "test-slow");
  request.set_id("no-such-planner");
  grpc::Status status = server.algorithms().GetAlgorithm(&c2, request, &algorithm);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(status.error_message().find("test-slow"), std::string::npos) << status.error_message();
}

}  // namespace
}  // namespace swarmplan::testing
