#include <catch2/catch.hpp>

#include "experiments/point_sources.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"

using namespace dtlab::experiments;

TEST_CASE("markdown_to_html renders the report subset", "[experiments]") {
  const std::string html = markdown_to_html(
      "# Title\n\ntext with `a<b` and **bold**\n\n| x | y |\n| --- | ---: |\n| 1 | 2 |\n\n```sh\nrun <it>\n```\n\n"
      "- one\n- two\n\n![fig](f.png)\n",
      "t");
  CHECK(html.find("<h1>Title</h1>") != std::string::npos);
  CHECK(html.find("<code>a&lt;b</code>") != std::string::npos);
  CHECK(html.find("<b>bold</b>") != std::string::npos);
  CHECK(html.find("<th>x</th><th>y</th>") != std::string::npos);
  CHECK(html.find("<td>1</td><td>2</td>") != std::string::npos);
  CHECK(html.find("---") == std::string::npos);
  CHECK(html.find("<pre>run &lt;it&gt;\n</pre>") != std::string::npos);
  CHECK(html.find("<li>two</li>") != std::string::npos);
  CHECK(html.find("<img src=\"f.png\" alt=\"fig\">") != std::string::npos);
}

TEST_CASE("markdown_to_html renders figure captions, not literal stars", "[experiments]") {
  const std::string html = markdown_to_html("![A caption](f.png)\n\n*A caption*\n\nx * y and 2 * 3\n", "t");
  CHECK(html.find("<em>A caption</em>") != std::string::npos);
  CHECK(html.find("*A caption*") == std::string::npos);
  CHECK(html.find("x * y and 2 * 3") != std::string::npos);  // a lone star stays text
}

TEST_CASE("rates carry their interval and counts; timing claims respect the spread", "[experiments]") {
  CHECK(rate_cell(5, 10) == "50.0% [23.7, 76.3] (5/10)");
  CHECK(rate_cell(0, 64) == "0.0% [0.0, 5.7] (0/64)");
  // reruns with one seed gave 0.61 and 0.87: a spread larger than the difference
  const Timing a{0.0610, 0.0511, 0.0870, 3}, b{0.0660, 0.0600, 0.0700, 3};
  CHECK(timing_claim(a, b).rfind("no measurable difference", 0) == 0);
  const Timing fast{0.050, 0.049, 0.051, 5}, slow{0.100, 0.098, 0.103, 5};
  CHECK(timing_claim(fast, slow).rfind("0.50x", 0) == 0);
  CHECK(timing_claim({0.5, 0.5, 0.5, 1}, slow).find("one run") != std::string::npos);
}

TEST_CASE("machine and version descriptions are filled", "[experiments]") {
  const auto m = machine_description();
  CHECK(m["hardware_threads"].get<unsigned>() >= 1);
  CHECK(!m["memory"].get<std::string>().empty());
  CHECK(version_description()["dtlab"] == "0.1.0");
  CHECK(!version_description()["git_commit"].get<std::string>().empty());
}

TEST_CASE("case seeds and point sources are reproducible", "[experiments]") {
  CHECK(case_seed(1, "a", 10, 0) == case_seed(1, "a", 10, 0));
  CHECK(case_seed(1, "a", 10, 0) != case_seed(1, "a", 10, 1));
  CHECK(case_seed(1, "a", 10, 0) != case_seed(1, "b", 10, 0));
  CHECK(experiment_points("torus-rays", 500, 3) == experiment_points("torus-rays", 500, 3));
  CHECK(experiment_points("torus-winding", 500, 3).size() == 500);
  CHECK(experiment_points("uniform", 100, 3).size() == 100);
  CHECK(is_point_source("torus-sdf"));
  CHECK_FALSE(is_point_source("torus-nothing"));
  CHECK_THROWS(experiment_points("nothing", 10, 1));
}
