// SPDX-License-Identifier: MIT
// Issue 24, item 16 (rest): under `mpirun -np K`, a hula built without MPI ran
// K independent copies of the command with interleaved output and exit 0. A
// command that does not use MPI (every command of a build without it) now
// refuses to run as one of several copies started by an MPI launcher, which
// it recognises by the launcher's environment (Open MPI, MPICH/Slurm PMI,
// PMIx). The launcher is played here by /usr/bin/env setting its variables.
#include "cli.hpp"

namespace hula::regress {
namespace {

// `hula args...` with the environment variables `vars` ("NAME=VALUE") set.
ProcessResult hula_with(const std::vector<std::string>& vars, const std::vector<std::string>& args) {
  std::vector<std::string> all = vars;
  all.emplace_back(HULA_CLI_PATH);
  all.insert(all.end(), args.begin(), args.end());
  return testing::run_process("/usr/bin/env", all);
}

// checks: `interpolate -o FILE` as one of several copies (each launcher's size or rank variable) exits 3 with
// Unsupported naming the variable and where.field "mpi", and writes nothing: no output file, no stdout.
TEST(Issue24MpiLauncher, CommandWithoutMpiRefusesToRunAsSeveralCopies) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  for (const std::string var :
       {"OMPI_COMM_WORLD_SIZE=4", "PMI_SIZE=2", "PMIX_SIZE=3", "OMPI_COMM_WORLD_RANK=1", "PMI_RANK=3", "PMIX_RANK=2"}) {
    const fs::path out = dir / "c.json";
    const ProcessResult r =
        hula_with({var}, {"interpolate", "--points", (dir / "points.csv").string(), "-o", out.string()});
    EXPECT_EQ(r.exit_code, 3) << var << ": " << r.err;
    const json e = error_of(r)["error"];
    EXPECT_EQ(e["code"], "Unsupported") << var;
    EXPECT_EQ(e["where"]["field"], "mpi") << var;
    EXPECT_NE(e["message"].get<std::string>().find(var), std::string::npos) << e["message"];
    EXPECT_EQ(r.out, "") << var;
    EXPECT_FALSE(fs::exists(out)) << var;
  }
}

// checks: one copy (size 1, rank 0: `mpirun -np 1`, or the first rank's own rank variable alone) and a value that
// is no number run the command as usual.
TEST(Issue24MpiLauncher, SingleCopyRunsAsUsual) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  const ProcessResult plain = hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", "-"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  for (const std::vector<std::string>& vars : std::vector<std::vector<std::string>>{
           {"OMPI_COMM_WORLD_SIZE=1", "OMPI_COMM_WORLD_RANK=0"}, {"PMIX_RANK=0"}, {"PMI_SIZE=many"}}) {
    const ProcessResult r = hula_with(vars, {"interpolate", "--points", (dir / "points.csv").string(), "-o", "-"});
    EXPECT_EQ(r.exit_code, 0) << vars.front() << ": " << r.err;
    EXPECT_EQ(r.out, plain.out) << vars.front();
  }
}

#if defined(HULA_WITH_MPI)
// checks: in a build with MPI, `optimise` without --islands is refused under a launcher (it would run K
// independent optimisations; with --islands it runs one island per rank, tests/mpi).
TEST(Issue24MpiLauncher, OptimiseNeedsIslandsUnderLauncher) {
  const std::vector<std::string> run{"optimise", "--problem",     "sphere", "--algorithm", "ga-real", "--dimension",
                                     "2",        "--generations", "2"};
  ASSERT_EQ(hula(run).exit_code, 0);
  const ProcessResult r = hula_with({"OMPI_COMM_WORLD_SIZE=2"}, run);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("hula optimise does not use MPI"), std::string::npos) << r.err;
}
#else
// checks: in a build without MPI, `batch` and `optimise --islands` are refused too.
TEST(Issue24MpiLauncher, BuildWithoutMpiRefusesEveryCommand) {
  const ProcessResult r =
      hula_with({"OMPI_COMM_WORLD_SIZE=2"}, {"optimise", "--problem", "sphere", "--algorithm", "ga-real", "--dimension",
                                             "2", "--generations", "2", "--islands", "2"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("built without MPI"), std::string::npos) << r.err;
}
#endif

}  // namespace
}  // namespace hula::regress
