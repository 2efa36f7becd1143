#pragma once

// The papers the planners follow (PlannerInfo::seed_paper): authors, title, venue, year. Where
// the copy of a paper the project holds does not name a field, the citation says so instead of
// guessing.

namespace swarmplan::citations {

// The five seed papers.
inline constexpr char kBeetleAntennae3d[] =
    "Improved beetle antennae search for 3D path planning with local fast search, ACO initial "
    "path generation and searching information orientation (LFS-BAS, ACO-BAS, SIO-BAS); "
    "authors, venue and year not named in the copy the project holds (laid out as an IEEE "
    "Access article)";
inline constexpr char kAsBfo[] =
    "Y. Long, Z. Zuo, Y. Su, J. Li, H. Zhang, \"An A*-based Bacterial Foraging Optimisation "
    "Algorithm for Global Path Planning of Unmanned Surface Vehicles\", The Journal of "
    "Navigation, 2020";
inline constexpr char kAemBso[] =
    "P. Ouyang, X. Kuang, J. Ye, \"Path planning based on improved beetle swarm optimization "
    "algorithm and cubic spline interpolation\" (in Chinese), Jiangxi University of Science and "
    "Technology; journal and year not named in the copy the project holds (its experiments ran "
    "in MATLAB R2024b)";
inline constexpr char kIdafsa[] =
    "F.-F. Li, Y. Du, K.-J. Jia, \"Path planning and smoothing of mobile robot based on improved "
    "artificial fish swarm algorithm\", Scientific Reports 12, 2022";
inline constexpr char kImprovedBinaryPso[] =
    "Q. Zhang, G. Gu, \"Path Planning Based on Improved Binary Particle Swarm Optimization "
    "Algorithm\", IEEE Conference on Robotics, Automation and Mechatronics, 2008";

// The classics the seed papers compare against or build on.
inline constexpr char kAStar[] =
    "P. E. Hart, N. J. Nilsson, B. Raphael, \"A Formal Basis for the Heuristic Determination of "
    "Minimum Cost Paths\", IEEE Transactions on Systems Science and Cybernetics 4(2), 1968";
inline constexpr char kDijkstra[] =
    "E. W. Dijkstra, \"A note on two problems in connexion with graphs\", Numerische Mathematik "
    "1, 1959";
inline constexpr char kThetaStar[] =
    "A. Nash, K. Daniel, S. Koenig, A. Felner, \"Theta*: Any-Angle Path Planning on Grids\", "
    "AAAI Conference on Artificial Intelligence, 2007";
inline constexpr char kAnya[] =
    "D. Harabor, A. Grastien, D. Oz, V. Aksakalli, \"Optimal Any-Angle Pathfinding In "
    "Practice\", Journal of Artificial Intelligence Research 56, 2016";
inline constexpr char kVisibilityGraph[] =
    "T. Lozano-Perez, M. A. Wesley, \"An algorithm for planning collision-free paths among "
    "polyhedral obstacles\", Communications of the ACM 22(10), 1979";
inline constexpr char kPso[] =
    "J. Kennedy, R. Eberhart, \"Particle swarm optimization\", IEEE International Conference on "
    "Neural Networks, 1995";
inline constexpr char kBat[] =
    "X.-S. Yang, \"A New Metaheuristic Bat-Inspired Algorithm\", Nature Inspired Cooperative "
    "Strategies for Optimization (NICSO 2010), Studies in Computational Intelligence 284, 2010";
inline constexpr char kGeneticAlgorithm[] =
    "J. H. Holland, \"Adaptation in Natural and Artificial Systems\", University of Michigan "
    "Press, 1975";
inline constexpr char kAntColony[] =
    "M. Dorigo, V. Maniezzo, A. Colorni, \"Ant system: optimization by a colony of cooperating "
    "agents\", IEEE Transactions on Systems, Man, and Cybernetics, Part B 26(1), 1996";
inline constexpr char kPotentialField[] =
    "O. Khatib, \"Real-time obstacle avoidance for manipulators and mobile robots\", The "
    "International Journal of Robotics Research 5(1), 1986";

}  // namespace swarmplan::citations
