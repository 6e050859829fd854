// Reference tests of the motion laws inclined-sine, scca, poly7, table and the inflection point λ
// of the modified sine and trapezoid (math.md §8), all through MotionDesign as a project uses
// them. Every expected number is independent of src/core/design: a closed form written out here
// (its source named where it is used), or the 40-digit reference
// tests/reference/motion_law_reference.py (Norton's SCCA acceleration integrated by quadrature,
// poly7's 8×8 system, the quintic spline's linear system), whose output is pasted below between
// its BEGIN/END markers. Rerun it with
//     /usr/bin/python3 tests/reference/motion_law_reference.py
// and paste its output over those lines; nothing here needs mpmath at run time.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/angles.h"
#include "core/test_projects.h"
#include "design/motion_design.h"
#include "design/motion_law.h"
#include "project/project.h"
#include "test_support.h"

namespace cam {
namespace law_reference {  // a named namespace: the release preset is a unity build
namespace {

using test::relClose;

/// A reference point: x (or u), y and its first three derivatives.
struct RefRow {
    double x, y, v, a, j;
};

// clang-format off
// BEGIN motion_law_reference.py
// scca b = 0.3, d = 0.5: Ca 5.3215338715685377 (quadrature; equals the closed form), Cv 1.8872708599425883
constexpr double kScca30x50Ca = 5.3215338715685377, kScca30x50Cv = 1.8872708599425883;
// x, y, y', y'', y''' (Norton's definition, mpmath.quad)
constexpr RefRow kScca30x50[] = {
    {0.02, 7.4139836045687696e-5, 0.011104713025466304, 1.1064091049817916, 54.509204338619044},
    {0.04, 5.8922792651242644e-4, 0.043933522856327218, 2.1644628229359536, 50.909122494294705},
    {0.11, 0.011567368191016208, 0.30147807784931356, 4.8614630960626815, 22.666201678346057},
    {0.2, 0.059759157838980276, 0.77424574587307734, 5.3215338715685377, 0.0},
    {0.26, 0.11579257603598318, 1.0935027707886708, 5.3110330400617816, -2.0994753288667566},
    {0.37, 0.26649600760246955, 1.6200985295695499, 3.879231242133867, -22.888642602701778},
    {0.45, 0.40632961470469523, 1.8458182537254375, 1.644444402456587, -31.799700134468274},
    {0.5, 0.5, 1.8872708599425883, 0.0, -33.436183433497937},
    {0.58, 0.64816427673806458, 1.7825089979804403, -2.5636684944848685, -29.300350897946209},
    {0.66, 0.78026364071656695, 1.4941400971157654, -4.4931196542701702, -17.916003005501022},
    {0.73, 0.87300728179911444, 1.1464732236538318, -5.2795719875260966, -4.1906649877695172},
    {0.81, 0.94771722292617207, 0.72103040715739196, -5.3215338715685377, 0.0},
    {0.89, 0.98843263180898379, 0.30147807784931356, -4.8614630960626815, 22.666201678346057},
    {0.97, 0.99975046322734313, 0.024871563730290477, -1.644444402456587, 52.999500224113791},
    {0.995, 0.99999883918054261, 6.964280249709501e-4, -0.27850756384775448, 55.650600510271059},
};
// scca b = 0.1, d = 0.2: Ca 4.3400845152286221 (quadrature; equals the closed form), Cv 1.9334771227511542
constexpr double kScca10x20Ca = 4.3400845152286221, kScca10x20Cv = 1.9334771227511542;
// x, y, y', y'', y''' (Norton's definition, mpmath.quad)
constexpr RefRow kScca10x20[] = {
    {0.02, 1.7824205195750615e-4, 0.026384145775168376, 2.5510376717543116, 110.30766816385208},
    {0.04, 0.0013437675292985047, 0.095458736178691127, 4.1276656594798737, 42.13378001884679},
    {0.11, 0.018611137014279068, 0.39855425172076283, 4.3400845152286221, 0.0},
    {0.2, 0.072058361955823642, 0.78916185809133882, 4.3400845152286221, 0.0},
    {0.26, 0.12722022556871549, 1.0495669290050561, 4.3400845152286221, 0.0},
    {0.37, 0.26893009907640483, 1.5269762256802046, 4.3400845152286221, 0.0},
    {0.45, 0.40470326578871472, 1.8525512062651199, 3.0689031916408885, -48.206218607186423},
    {0.5, 0.5, 1.9334771227511542, 0.0, -68.173888145005292},
    {0.58, 0.64930309970289832, 1.742559650393772, -4.1276656594798737, -21.066890009423395},
    {0.66, 0.77492614966214843, 1.3967736902233459, -4.3400845152286221, 0.0},
    {0.73, 0.86206710091547252, 1.0929677741573424, -4.3400845152286221, 0.0},
    {0.81, 0.93561625239932832, 0.7457610129390526, -4.3400845152286221, 0.0},
    {0.89, 0.98138886298572093, 0.39855425172076283, -4.3400845152286221, 0.0},
    {0.97, 0.99941311613382105, 0.056947129712377775, -3.5112021298435106, 80.143212086141557},
    {0.995, 0.9999971629236927, 0.0017008456611570805, -0.67893879936917922, 134.66910890771762},
};
// scca b = 0.6, d = 0.15: Ca 6.3706792696743923 (quadrature; equals the closed form), Cv 2.3172225536419169
constexpr double kScca60x15Ca = 6.3706792696743923, kScca60x15Cv = 2.3172225536419169;
// x, y, y', y'', y''' (Norton's definition, mpmath.quad)
constexpr RefRow kScca60x15[] = {
    {0.02, 4.4451351355468767e-5, 0.0066652653216329844, 0.66591731403016116, 33.174066620107497},
    {0.04, 3.5502629726876311e-4, 0.026588035244871688, 1.3245386986156511, 32.627872570895587},
    {0.11, 0.0072778810795990042, 0.19629115198064067, 3.4697206098256985, 27.975365271412458},
    {0.2, 0.042099789907294649, 0.60835505797304715, 5.5171700869009183, 16.678399326654883},
    {0.26, 0.089048055714291134, 0.96374185850466982, 6.2314646426766, 6.9352684082771913},
    {0.37, 0.23341639199547633, 1.6626576648233018, 6.3706792696743923, 0.0},
    {0.45, 0.38677010918711007, 2.1651337891486551, 5.5171700869009183, -66.713597306619534},
    {0.5, 0.5, 2.3172225536419169, 0.0, -133.42719461323907},
    {0.58, 0.67548737567626559, 1.9811916283070214, -6.3706792696743923, 0.0},
    {0.66, 0.81359653227786924, 1.47153728673307, -6.3706792696743923, 0.0},
    {0.73, 0.901001867925366, 1.0263747198490298, -6.2922456363285444, 5.2181529527852069},
    {0.81, 0.96371074453801717, 0.55404229250419178, -5.3429012012959618, 18.167414629729186},
    {0.89, 0.992722118920401, 0.19629115198064067, -3.4697206098256985, 27.975365271412458},
    {0.97, 0.99985007948265917, 0.014979720541978799, -0.99659380349440225, 32.946121109453648},
    {0.995, 0.99999930509050932, 4.169361687215325e-4, -0.16676494192830566, 33.345368111515913},
};
// scca b = 0, d = 0.6: Ca 4.2927436124916671 (quadrature; equals the closed form), Cv 1.6784023609233836
constexpr double kScca0x60Ca = 4.2927436124916671, kScca0x60Cv = 1.6784023609233836;
// x, y, y', y'', y''' (Norton's definition, mpmath.quad)
constexpr RefRow kScca0x60[] = {
    {0.02, 8.5854872249833341e-4, 0.085854872249833341, 4.2927436124916671, 0.0},
    {0.04, 0.0034341948899933337, 0.17170974449966668, 4.2927436124916671, 0.0},
    {0.11, 0.025971098855574586, 0.47220179737408338, 4.2927436124916671, 0.0},
    {0.2, 0.085854872249833341, 0.85854872249833341, 4.2927436124916671, 0.0},
    {0.26, 0.145031391288391, 1.1118974296718073, 4.0826417854445976, -6.9456986536933812},
    {0.37, 0.28984935766149375, 1.4956946665861648, 2.7015110888899478, -17.467717816404153},
    {0.45, 0.41654654553622604, 1.650466525630149, 1.1110438026550387, -21.71087620858551},
    {0.5, 0.5, 1.6784023609233836, 0.0, -22.476752994580552},
    {0.58, 0.63237092921537123, 1.6075222898132973, -1.7460161265299444, -20.533535600753791},
    {0.66, 0.75372979212048496, 1.4071378847032033, -3.1901302027243188, -15.039883360241967},
    {0.73, 0.84364670641576883, 1.1523579898279726, -4.0076214125931091, -8.0549478831040202},
    {0.81, 0.92251597779452541, 0.81562128637341674, -4.2927436124916671, 0.0},
    {0.89, 0.97402890114442541, 0.47220179737408338, -4.2927436124916671, 0.0},
    {0.97, 0.99806826537437875, 0.12878230837475001, -4.2927436124916671, 0.0},
    {0.995, 0.99994634070484385, 0.021463718062458335, -4.2927436124916671, 0.0},
};
// u, s, s', s'', s''' per rad: poly7 0..150 deg, lift 0 -> 12 (8x8 system, mpmath)
constexpr RefRow kPoly7Rise[] = {
    {0.03, 0.24392460943603125, 3.3321415881120204, 5.449808446320625, -10.064091644330337},
    {0.1, 0.9395158125, 4.2403682523187577, 4.7985601119709162, 1.0279170352708021},
    {0.21, 2.3685371984944687, 5.7193631530053455, 5.4588812482041652, 0.97281438113350186},
    {0.33, 4.4283086482913437, 7.3321687607916896, 4.2688450012494621, -9.1211917179236524},
    {0.4, 5.832768, 7.9277190731717327, 2.0589761427273657, -14.716235835240175},
    {0.5, 7.9306640625, 7.9027889633083467, -2.4108109132898743, -18.378053123742231},
    {0.57, 9.3197103878460937, 7.1559572045202433, -5.6932661088926717, -16.858455846525894},
    {0.68, 11.084001705984, 4.9157088469103789, -9.43588763246893, -7.9787077020177007},
    {0.79, 12.089229589475906, 2.0446024536580355, -9.8671915015713386, 5.1504121615951407},
    {0.9, 12.3011983125, -0.42416137193259233, -6.8206046832606498, 14.480181694478079},
    {0.97, 12.124030400837344, -1.4278066477048574, -4.1760339350937715, 12.992405330497251},
};
constexpr double kPoly7RiseTerms[] = {1314.0, 2556.5376818737332, 4228.254578815126, 5748.6863655980389};
// u, s, s', s'', s''' per rad: poly7 150..360 deg, lift 12 -> 0 (8x8 system, mpmath)
constexpr RefRow kPoly7Return[] = {
    {0.03, 11.793107096570521, -2.027755632703249, -2.3780599880243873, 7.0824234270622899},
    {0.1, 11.2110282225, -2.4586646015911396, -1.1780514727334643, 2.4798256164864348},
    {0.21, 10.136074521256817, -2.8762668984508372, -1.1891690363723766, -1.9122009029670108},
    {0.33, 8.7224980781562982, -3.6351011031148767, -2.2948679196520996, -2.3783033253378354},
    {0.4, 7.70851584, -4.2878144576151948, -2.7240914681331736, -0.76618272210934931},
    {0.5, 5.9548828125, -5.2573353936027489, -2.3228786003431312, 3.1948271280340374},
    {0.57, 4.5408557482256842, -5.7126771161202329, -1.0877833358850605, 6.4314206925434652},
    {0.68, 2.232354439299072, -5.5037129459990328, 2.3976710190299961, 10.442226421825847},
    {0.79, 0.32639465341565775, -3.6557167941054938, 6.7516083945233993, 10.102807076078198},
    {0.9, -0.5040669975, -0.28168854067977157, 9.3896398280360544, 1.1439960208248438},
    {0.97, -0.27157732263424575, 2.0448355461977584, 8.2123579194665967, -11.3708379265399},
};
constexpr double kPoly7ReturnTerms[] = {505.95, 618.50793984372365, 681.41680379529482, 651.79271650384526};
// x, y, y', y'', y''' of the quintic spline (mpmath)
constexpr RefRow kTable6[] = {
    {0.0123, 4.2387636347274571e-5, 0.01014866168710198, 1.5890816425972291, 114.53813795640996},
    {0.0373, 0.0010551045692622982, 0.079994844546569213, 3.784495422192112, 63.149922604080954},
    {0.0623, 0.0043742465827483969, 0.18995190346886838, 4.849325682446291, 24.091456409153643},
    {0.0873, 0.010681386950346466, 0.31560829708216991, 5.0918161522948083, -2.6372606283719718},
    {0.1123, 0.020144136576593862, 0.4402585772380203, 4.8202105606727065, -17.03622850849589},
    {0.1373, 0.032608796327608805, 0.5549033890113421, 4.342752636515028, -19.105447231218112},
    {0.1623, 0.047792954963673471, 0.65822735769177196, 3.9604948864277253, -10.598873462170274},
    {0.1873, 0.06546446258169167, 0.75483956292438793, 3.8027087650374007, -2.3843375767665454},
    {0.2123, 0.085521951682939327, 0.84984895675661516, 3.8232619412038557, 3.668270342372103},
    {0.2373, 0.10797545299214773, 0.94703841913791532, 3.9681062157704635, 7.5589502952456712},
    {0.2623, 0.13291267917054828, 1.0488396250388344, 4.183193389580597, 9.2877022818541591},
    {0.2873, 0.16046524469139956, 1.1563330444510027, 4.4144752634776291, 8.8545263021975666},
    {0.3123, 0.19077488571551448, 1.2692479423871348, 4.607903638304933, 6.2594223562758939},
    {0.3373, 0.22395967996678736, 1.3859623788810297, 4.7094303149058815, 1.5023904440891408},
    {0.3623, 0.26008026660772105, 1.5035032089875707, 4.6650070941238477, -5.4165694343626925},
    {0.3873, 0.29910606611495404, 1.6175460827827253, 4.4205857768022045, -14.497457279079606},
    {0.4123, 0.3408815178411947, 1.7224226349599434, 3.9244562439136887, -25.170009643875328},
    {0.4373, 0.38509674730386639, 1.8116925589867331, 3.1807595024085253, -33.900771840905746},
    {0.4623, 0.43129024326714481, 1.8799072999365916, 2.2506655436500017, -40.081787024144131},
    {0.4873, 0.47888401698989673, 1.9232037233199951, 1.197918042982919, -43.713055193590484},
    {0.5123, 0.52722342126729612, 1.9393122865310396, 0.086260675752077815, -44.794576349244803},
    {0.5373, 0.57561699022791457, 1.9275570388474411, -1.0205628826977209, -43.326350491107091},
    {0.5623, 0.62337627043428821, 1.8888520862583303, -2.0599586065193257, -39.588779935677164},
    {0.5873, 0.66985347385749824, 1.8254202988094519, -2.9967948387197433, -35.319287774588711},
    {0.6123, 0.71446339142416258, 1.7399260911470079, -3.8239814519603845, -30.816810418895046},
    {0.6373, 0.75668933486714465, 1.6351835116183069, -4.5356938163761189, -26.081347868596168},
    {0.6623, 0.79608678732482342, 1.5141522243172856, -5.1261073021018161, -21.112900123692078},
    {0.6873, 0.83228704373475913, 1.3799375090845092, -5.589397279272346, -15.911467184182775},
    {0.7123, 0.86500085122735902, 1.2357902615071708, -5.9197391180225781, -10.47704905006826},
    {0.7373, 0.894022049519543, 1.0851069929190922, -6.1113081884873822, -4.8096457213485321},
    {0.7623, 0.91923121130840937, 0.93142983040072304, -6.158279860801628, 1.0907428019764083},
    {0.7873, 0.94059928266490054, 0.77844651677914151, -6.054829505100185, 7.2241165199065611},
    {0.8123, 0.95819122037525435, 0.62998916989050429, -5.7955359834039889, 13.492062777303936},
    {0.8373, 0.97216886482671119, 0.48993555744333833, -5.3846166110429665, 19.284799095621012},
    {0.8623, 0.98278828883450894, 0.361904729457199, -4.8361304244207804, 24.497407918197029},
    {0.8873, 0.99039154089094306, 0.24915456644619629, -4.1645806109309572, 29.129889245031985},
    {0.9123, 0.99539758425510128, 0.15458036923960206, -3.3844703579670233, 33.182243076125882},
    {0.9373, 0.99829323246074264, 0.080714858981849989, -2.5103028529225053, 36.65446941147872},
    {0.9623, 0.99962408482417655, 0.029728177132535608, -1.5565812831909295, 39.546568251090497},
    {0.9873, 0.99998546195214183, 0.0034278854664162735, -0.53780883616582256, 41.858539594961216},
};
// x, y, y', y'', y''' of the quintic spline (mpmath)
constexpr RefRow kTable6V[] = {
    {0.0123, 6.5551884698533452e-5, 0.0155219078626, 2.3744122639397493, 157.47270656942657},
    {0.0373, 0.0015219921311945182, 0.11093038983015768, 4.7776619783914143, 42.127670951798359},
    {0.0623, 0.0058429557046508231, 0.2349625412566805, 4.8478158297842534, -29.174962475279512},
    {0.0873, 0.013129635640040252, 0.34305421625024479, 3.6859338728820249, -56.435193711807045},
    {0.1123, 0.02271320259215119, 0.41816777028802084, 2.3930761624484873, -39.653022757784239},
    {0.1373, 0.033842967369814956, 0.4707920602162729, 2.0703027532473991, 21.171550386788905},
    {0.1623, 0.046369572046218854, 0.53731298183470853, 3.4160653094409053, 58.889670949018161},
    {0.1873, 0.061010643949397529, 0.63910856208548479, 4.6496134325288171, 40.177428206847419},
    {0.2123, 0.078534856416115475, 0.76613480037455088, 5.4440991852249084, 23.76468131767253},
    {0.2373, 0.099441757177033002, 0.9081337298961725, 5.8570099638540757, 9.6514302814934935},
    {0.2623, 0.1239924096040186, 1.0562845687527378, 5.9458331647412152, -2.1623249016896897},
    {0.2873, 0.15224532233285197, 1.2032037199547572, 5.7680561842112233, -11.67658423187702},
    {0.3123, 0.18409237888592715, 1.3429447714208636, 5.3811664185889963, -18.891347709068497},
    {0.3373, 0.21929476729495548, 1.4709984959778125, 4.8426512641994305, -23.806615333264121},
    {0.3623, 0.25751890972366874, 1.5842928513604815, 4.2099981173674223, -26.422387104463892},
    {0.3873, 0.29837239209052218, 1.6811929802118707, 3.540694374417868, -26.738663022667811},
    {0.4123, 0.34143987870833443, 1.7614951194070199, 2.8902467240064136, -25.238542519400353},
    {0.4373, 0.38631527427509438, 1.8259419666757852, 2.2668474996600875, -24.915396399735715},
    {0.4623, 0.43260676872602388, 1.874728565891144, 1.6303768554481286, -26.284256108650979},
    {0.4873, 0.47991436477590116, 1.9069993797350239, 0.93853464565603937, -29.345121646146146},
    {0.5123, 0.52780345791101687, 1.9208413672464907, 0.14902072456932214, -34.097993012221216},
    {0.5373, 0.57577839879810252, 1.9132839838217473, -0.78046505352652061, -40.542870206876188},
    {0.5623, 0.62325654671882042, 1.8804594394766573, -1.8529016511757874, -42.210031717209019},
    {0.5873, 0.66958211875741485, 1.8214336305379665, -2.8494677319144563, -37.483152036004004},
    {0.6123, 0.71413305365600916, 1.7389908836723608, -3.7254541176819635, -32.563656119516088},
    {0.6373, 0.75636211072588835, 1.6362058838276452, -4.4760454025962365, -27.451543967745269},
    {0.6623, 0.79580042121637069, 1.5162737010986765, -5.0964261807752027, -22.146815580691549},
    {0.6873, 0.83206049794348401, 1.3825097907273633, -5.5817810463367897, -16.649470958354926},
    {0.7123, 0.86483924491864202, 1.2383499931026658, -5.9272945933989249, -10.959510100735402},
    {0.7373, 0.89392096697732058, 1.0873505337605964, -6.1281514160795356, -5.0769330078329758},
    {0.7623, 0.91918037940773399, 0.93318802338421901, -6.1795361084965495, 0.99826032035235235},
    {0.7873, 0.9405856175795113, 0.7796594578036495, -6.0766332647678938, 7.2660698838205825},
    {0.8123, 0.95820124354319611, 0.63068098662348555, -5.8150279253757112, 13.628825837641213},
    {0.8373, 0.97219049394404789, 0.49018993325488969, -5.3998708338993638, 19.481348288663664},
    {0.8623, 0.98281204557224852, 0.36184272469427021, -4.8460801705326737, 24.719511588868631},
    {0.8873, 0.99041121764559123, 0.24891321300425521, -4.169014914046078, 29.343315738256113},
    {0.9123, 0.99541037600256918, 0.15429127577821188, -3.3840340432100138, 33.352760736826112},
    {0.9373, 0.99829933374064394, 0.080482816140246453, -2.5064965367949181, 36.747846584578626},
    {0.9623, 0.99962575185451399, 0.029609762745204258, -1.5517613735712282, 39.528573281513657},
    {0.9873, 0.99998553987438318, 0.0034100697786696876, -0.53518753230938101, 41.694940827631203},
};
// x, y, y', y'', y''' of the spline with y'(0) = y'(1) = 3
constexpr RefRow kTableEndV[] = {
    {0.0123, 0.036810934687699483, 2.9785715319208349, -3.3890039825651709, -252.51390092753053},
    {0.0373, 0.109616790180085, 2.8241917952066947, -8.6029604236185481, -166.49441350013042},
    {0.0623, 0.17715041010822616, 2.5651618628226633, -11.808314614741231, -91.825720933074958},
    {0.0873, 0.23739366842186352, 2.2481496676231505, -13.288836427441835, -28.507823226364154},
    {0.1123, 0.28940645930725148, 1.9127288956748504, -13.328295733228977, 23.459279620001994},
    {0.1373, 0.33314934101746534, 1.591378986256742, -12.210462403611274, 64.075587606023486},
    {0.1623, 0.36930617970270841, 1.3094851318600886, -10.219106310097342, 93.341100731700322},
    {0.1873, 0.39910679324061916, 1.0853382781884384, -7.6379973241957965, 111.2558189970325},
    {0.2123, 0.42414959506657832, 0.93013512415762377, -4.7509053174152552, 117.81974240202003},
    {0.2373, 0.44622423800401599, 0.84797812189576209, -1.8416001612643339, 113.0328709466629},
    {0.2623, 0.46713425809471875, 0.83587547674325511, 0.8061482727483509, 96.895204630961111},
    {0.2873, 0.48851971842913679, 0.8837411472527892, 2.9085701131141829, 69.406743454914669},
    {0.3123, 0.51167991624671029, 0.97442056470936963, 4.1902595598804125, 32.607504871174039},
    {0.3373, 0.53741193660651537, 1.0857371280817871, 4.5756084198078706, -0.86219675405282499},
    {0.3623, 0.56596371547914769, 1.1968015057713354, 4.1930196883239993, -28.827502441732319},
    {0.3873, 0.59710330208964019, 1.290135381723215, 3.1801032638674828, -51.288412191864443},
    {0.4123, 0.63020479085491788, 1.3517006873435932, 1.6744690448770052, -68.244926004449197},
    {0.4373, 0.66433432757032208, 1.3708996014996046, -0.18627307020874899, -79.697043879486581},
    {0.4623, 0.69833611559613452, 1.3405745505193508, -2.2645131829510957, -85.644765816976595},
    {0.4873, 0.7309184220441016, 1.2570082081919006, -4.4226413949113506, -86.088091816919238},
    {0.5123, 0.7607395839639585, 1.1199234957672898, -6.5230478076508295, -81.027021879314512},
    {0.5373, 0.78649401452995339, 0.93248358195652128, -8.4281225227308482, -70.461556004162416},
    {0.5623, 0.80699820922737162, 0.70129188293156522, -10.000255641712722, -54.39169419146295},
    {0.5873, 0.82127675203905986, 0.43639206232535874, -11.101837266157768, -32.817436441216114},
    {0.6123, 0.82864832163195029, 0.15126803123180612, -11.5952574976273, -5.7387827534219076},
    {0.6373, 0.82881169754358483, -0.13715605179422127, -11.342906437682635, 26.844266871919669},
    {0.6623, 0.82193176636863922, -0.40851578073688495, -10.207174187885088, 64.931712434808615},
    {0.6873, 0.80872552794544728, -0.63900650211937931, -8.0504508497959761, 108.52355393524493},
    {0.7123, 0.7905480173975146, -0.80141752029273472, -4.7462501961320802, 154.90670084750508},
    {0.7373, 0.76945715226719595, -0.86785380261365855, -0.43380382135360817, 187.27035721267728},
    {0.7623, 0.74812628956701942, -0.81812694040231389, 4.4763350683970136, 202.72210204527705},
    {0.7873, 0.7296022453849378, -0.64257959313832588, 9.561368684805474, 201.26193534530438},
    {0.8123, 0.71704114501306498, -0.34212436500917746, 14.398499239557462, 182.88985711275927},
    {0.8373, 0.7134441743299796, 0.071756195089790694, 18.564928944338667, 147.60586734764171},
    {0.8623, 0.72139333118302854, 0.5770095935553801, 21.637860010834777, 95.409966049951725},
    {0.8873, 0.7427871767706305, 1.1410133920765345, 23.194494650731483, 26.302153219689297},
    {0.9123, 0.77857658702457954, 1.7205752076343399, 22.812035075714472, -59.717571143145571},
    {0.9373, 0.82850050399234867, 2.2619327125020246, 20.067683497469434, -162.64920703855288},
    {0.9623, 0.89082168721939337, 2.7007536342449588, 14.538642127682058, -282.49275446653262},
    {0.9873, 0.96206246513145515, 2.9621357557206554, 5.8021131780380325, -419.24821342708481},
};
// poly4567 sampled at x = k/20, k = 0..20, through the quintic spline: its largest
// deviation from the polynomial over 4001 points, for y, y', y'', y'''.
constexpr double kPoly4567SplineDeviation[] = {6.2259864556595306e-8, 3.6055082665467443e-6, 3.9594586868445148e-4, 0.058595765250143668};
// END motion_law_reference.py
// clang-format on

// ------------------------------------------------------------------------------------ helpers

using test::designSegment;

/// math.md §8's cam with `rise` (0–120°, 10 mm) and `ret` (180–300°, back to 0) between dwells.
DesignSpec restToRest(DesignSegmentSpec rise, DesignSegmentSpec ret) {
    rise.toDeg = 120.0;
    rise.lift = 10.0;
    ret.toDeg = 300.0;
    ret.lift = 0.0;
    DesignSpec d;
    d.baseRadius = 40.0;
    d.segments = {rise, designSegment(MotionLawType::Dwell, 180.0, 10.0), ret,
                  designSegment(MotionLawType::Dwell, 360.0, 0.0)};
    return d;
}

/// The built design, or none (and a failure naming the first error).
std::optional<MotionDesign> built(const DesignSpec& d) {
    const auto m = MotionDesign::build(d);
    if (m.ok()) return m.value();
    ADD_FAILURE() << m.errors().front().text();
    return std::nullopt;
}

/// Segment k of a design seen as its normalised law: y = (s − s0)/Δ, y' = s'·h/Δ, y'' = s''·h²/Δ,
/// y''' = s'''·h³/Δ, h the stretch in rad (what MotionDesign::coefficients normalises by).
struct SegmentView {
    const MotionDesign* m;
    double phi0, h, s0, delta;

    [[nodiscard]] LawPoint at(double x) const {
        const std::array<double, 4> s = m->liftAt(phi0 + x * h);
        return {(s[0] - s0) / delta, s[1] * h / delta, s[2] * h * h / delta,
                s[3] * h * h * h / delta};
    }
};

SegmentView viewOf(const MotionDesign& m, std::size_t k) {
    const auto& seg = m.spec().segments;
    const double fromDeg = k == 0 ? 0.0 : seg[k - 1].toDeg, s0 = k == 0 ? 0.0 : seg[k - 1].lift;
    return {&m, degToRad(fromDeg), degToRad(seg[k].toDeg - fromDeg), s0, seg[k].lift - s0};
}

/// max |f| over [0, 1): 200 000 samples, the best refined by ternary sections (a supremum at
/// x → 1 is approached from the left: x = 1 is the next segment's).
double peak(const std::function<double(double)>& f) {
    constexpr int n = 200000;
    const double last = 1.0 - 1e-12;
    int best = 0;
    double found = -1.0;
    for (int i = 0; i <= n; ++i) {
        const double value = std::abs(f(std::min(static_cast<double>(i) / n, last)));
        if (value > found) std::tie(best, found) = std::pair(i, value);
    }
    double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(last, (best + 1.0) / n);
    for (int it = 0; it < 100; ++it) {
        const double a = lo + (hi - lo) / 3.0, b = hi - (hi - lo) / 3.0;
        const double fa = std::abs(f(a)), fb = std::abs(f(b));
        found = std::max({found, fa, fb});
        (fa < fb ? lo : hi) = fa < fb ? a : b;
    }
    return found;
}

/// Cv, Ca, Cj of a normalised segment by dense sampling.
LawCoefficients sampled(const SegmentView& s) {
    return {peak([&](double x) { return s.at(x).v; }), peak([&](double x) { return s.at(x).a; }),
            peak([&](double x) { return s.at(x).j; })};
}

/// |got − want| ≤ tol·max(1, |want|) + dx·|want'| for y, y', y'' (dx: how far x itself may be
/// off, so want' the next derivative) and 10·tol·max(1, |want|) for y''' (tens to thousands),
/// each message naming what and where.
void expectPoint(const LawPoint& got, const LawPoint& want, double tol, const std::string& what,
                 bool checkJerk = true, double dx = 0.0) {
    const auto near = [&](double g, double w, double next) {
        const double bound = tol * std::max(1.0, std::abs(w)) + dx * std::abs(next);
        if (std::abs(g - w) <= bound) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "got " << g << " want " << w << ": difference "
                                             << std::abs(g - w) << " > " << bound;
    };
    EXPECT_TRUE(near(got.y, want.y, want.v)) << what << " y";
    EXPECT_TRUE(near(got.v, want.v, want.a)) << what << " y'";
    EXPECT_TRUE(near(got.a, want.a, want.j)) << what << " y''";
    if (checkJerk) {
        EXPECT_TRUE(relClose(got.j, want.j, 10 * tol, 1.0)) << what << " y'''";
    }
}

/// expectPoint for segment s at x. The design finds x as (φ − φ0)/h from φ = φ0 + x·h, so x is
/// known to a few ulps of φ/h: dx = 8ε·(φ0 + h)/h (with y''' up to ~1700, as for λ = 0.9, that
/// is ~1e-12 in y'').
void expectAt(const SegmentView& s, double x, const LawPoint& want, double tol,
              const std::string& what, bool checkJerk = true) {
    const double dx = 8 * std::numeric_limits<double>::epsilon() * (s.phi0 + s.h) / s.h;
    expectPoint(s.at(x), want, tol, what, checkJerk, dx);
}

// ------------------------------------------------------------- the classic laws, written out
// y, y', y'', y''' on [0, 1]. Symmetric laws are written for x ≤ 1/2 and mirrored:
// y(x) = 1 − y(1 − x), y' even, y'' odd, y''' even about x = 1/2.

LawPoint mirrored(LawPoint (*half)(double), double x) {
    if (x <= 0.5) return half(x);
    const LawPoint p = half(1.0 - x);
    return {1.0 - p.y, p.v, -p.a, p.j};
}

/// The cycloid y = x − sin(2πx)/(2π) (VDI 2143 Blatt 1; math.md §8).
LawPoint cycloid(double x) {
    const double w = kTwoPi;
    return {x - std::sin(w * x) / w, 1.0 - std::cos(w * x), w * std::sin(w * x),
            w * w * std::cos(w * x)};
}

/// The harmonic (simple harmonic) law y = (1 − cos πx)/2.
LawPoint harmonic(double x) {
    return {(1.0 - std::cos(kPi * x)) / 2.0, kPi / 2.0 * std::sin(kPi * x),
            kPi * kPi / 2.0 * std::cos(kPi * x), -kPi * kPi * kPi / 2.0 * std::sin(kPi * x)};
}

/// Constant acceleration (the parabola): y = 2x² to x = 1/2.
LawPoint parabolaHalf(double x) { return {2.0 * x * x, 4.0 * x, 4.0, 0.0}; }

/// The sine ramp both modified laws start with, a = A·sin 4πx on [0, 1/8].
LawPoint sineRamp(double A, double x) {
    const double w = 4.0 * kPi;
    return {A * (x / w - std::sin(w * x) / (w * w)), A * (1.0 - std::cos(w * x)) / w,
            A * std::sin(w * x), A * w * std::cos(w * x)};
}

/// The modified trapezoid (Norton, Cam Design and Manufacturing Handbook, 2nd ed., ch. 3;
/// Rothbart, Cam Design Handbook, 2004): a = A sin 4πx to 1/8, A to 3/8, A cos 4π(x − 3/8) to
/// 1/2, with A = Ca = 8π/(π + 2) = 4.8881 (from y(1/2) = 1/2; math.md: 4.8881).
LawPoint modifiedTrapezoidHalf(double x) {
    const double A = 8.0 * kPi / (kPi + 2.0), w = 4.0 * kPi;
    if (x <= 0.125) return sineRamp(A, x);
    const double v1 = A / w, y1 = A * (1.0 / (8.0 * w) - 1.0 / (w * w));
    if (x <= 0.375) {
        const double t = x - 0.125;
        return {y1 + v1 * t + A * t * t / 2.0, v1 + A * t, A, 0.0};
    }
    const double v2 = v1 + A / 4.0, y2 = y1 + v1 / 4.0 + A / 32.0, t = x - 0.375;
    return {y2 + v2 * t + A * (1.0 - std::cos(w * t)) / (w * w), v2 + A * std::sin(w * t) / w,
            A * std::cos(w * t), -A * w * std::sin(w * t)};
}

/// The modified sine (same sources): a = A sin 4πx to 1/8, then A cos(4π(x − 1/8)/3) to 7/8,
/// with A = Ca = 4π²/(4 + π) = 5.5280 (math.md: 5.5280).
LawPoint modifiedSineHalf(double x) {
    const double A = 4.0 * kPi * kPi / (4.0 + kPi), w = 4.0 * kPi;
    if (x <= 0.125) return sineRamp(A, x);
    const double v1 = A / w, y1 = A * (1.0 / (8.0 * w) - 1.0 / (w * w));
    const double u = w / 3.0, t = x - 0.125;
    return {y1 + v1 * t + A * (1.0 - std::cos(u * t)) / (u * u), v1 + A * std::sin(u * t) / u,
            A * std::cos(u * t), -A * u * std::sin(u * t)};
}

LawPoint modifiedTrapezoid(double x) { return mirrored(modifiedTrapezoidHalf, x); }
LawPoint modifiedSine(double x) { return mirrored(modifiedSineHalf, x); }
LawPoint parabola(double x) { return mirrored(parabolaHalf, x); }

/// Their coefficients in closed form (the sine ramp's jerk 4πA at x = 0 is the largest).
constexpr double kTrapezoidCa = 8.0 * kPi / (kPi + 2.0);
constexpr double kSineCa = 4.0 * kPi * kPi / (4.0 + kPi);
const LawCoefficients kTrapezoid{2.0, kTrapezoidCa, 4.0 * kPi* kTrapezoidCa};
const LawCoefficients kSine{kSineCa / kPi, kSineCa, 4.0 * kPi* kSineCa};

/// poly 4-5-6-7: y = 35x⁴ − 84x⁵ + 70x⁶ − 20x⁷.
LawPoint poly4567(double x) {
    const double x2 = x * x, x3 = x2 * x, x4 = x3 * x;
    return {x4 * (35.0 - 84.0 * x + 70.0 * x2 - 20.0 * x3),
            x3 * (140.0 - 420.0 * x + 420.0 * x2 - 140.0 * x3),
            x2 * (420.0 - 1680.0 * x + 2100.0 * x2 - 840.0 * x3),
            x * (840.0 - 5040.0 * x + 8400.0 * x2 - 4200.0 * x3)};
}

/// A symmetric law Y with its inflection point moved to λ (CODESYS SoftMotion's inflection point
/// parameter λ): y = 2λ·Y(x/2λ) for x ≤ λ, 1 − 2(1 − λ)·Y((1 − x)/2(1 − λ)) after.
LawPoint withInflection(LawPoint (*Y)(double), double lambda, double x) {
    if (x <= lambda) {
        const LawPoint p = Y(x / (2.0 * lambda));
        return {2.0 * lambda * p.y, p.v, p.a / (2.0 * lambda), p.j / (4.0 * lambda * lambda)};
    }
    const double mu = 1.0 - lambda;
    const LawPoint p = Y((1.0 - x) / (2.0 * mu));
    return {1.0 - 2.0 * mu * p.y, p.v, -p.a / (2.0 * mu), p.j / (4.0 * mu * mu)};
}

/// Bestehorn's inclined sine ("geneigte Sinuslinie", cf. VDI 2143 Blatt 1) with normalised end
/// velocity vn: y = vn·x + (1 − vn)·(x − sin 2πx/2π).
LawPoint inclinedSine(double vn, double x) {
    const LawPoint c = cycloid(x);
    return {vn * x + (1.0 - vn) * c.y, vn + (1.0 - vn) * c.v, (1.0 - vn) * c.a, (1.0 - vn) * c.j};
}

/// Norton's SCCA: Ca = 4π²/((π² − 8)(b² − d²) − 2π(π − 2)b + π²), Cv = Ca(b/π + c/2 + d/π),
/// Cj = Ca·π/min(b, d) over the positive ones (Norton, Cam Design and Manufacturing Handbook,
/// 2nd ed., ch. 3). The Ca of four generic (b, d) is checked against the quadrature below.
LawCoefficients sccaCoefficients(double b, double d) {
    const double pi2 = kPi * kPi;
    const double ca =
        4.0 * pi2 / ((pi2 - 8.0) * (b * b - d * d) - 2.0 * kPi * (kPi - 2.0) * b + pi2);
    const double c = 1.0 - b - d;
    double smallest = 0.0;
    for (double share : {b, d}) {
        if (share > 0.0 && (smallest == 0.0 || share < smallest)) smallest = share;
    }
    return {ca * (b / kPi + c / 2.0 + d / kPi), ca, smallest > 0.0 ? ca * kPi / smallest : 0.0};
}

/// The coefficients of a law without a closed form (poly5, poly7, table) may be found by
/// sampling: a maximum of f sampled every δ is low by at most |f''|·δ²/8, with δ = 1/20 000 at
/// most 2e-8 relative for every poly7 here (e.g. poly4567's Ca = 7.51 where |y''''| = 376). 1e-6
/// relative allows that and still catches a wrong normalisation (h in degrees, a missing 1/Δ).
constexpr double kSampledCoefficients = 1e-6;

void expectCoefficients(const LawCoefficients& got, const LawCoefficients& want, double rel,
                        const std::string& what) {
    EXPECT_TRUE(relClose(got.cv, want.cv, rel, 1e-12)) << what << " Cv";
    EXPECT_TRUE(relClose(got.ca, want.ca, rel, 1e-12)) << what << " Ca";
    EXPECT_TRUE(relClose(got.cj, want.cj, rel, 1e-12)) << what << " Cj";
}

/// Samples of x off every piece boundary of the laws here (1/8, 3/8, 5/8, 7/8, λ, b/2, …).
std::vector<double> samplesOfX() {
    std::vector<double> xs;
    for (double x = 0.0037; x < 1.0; x += 0.0191) xs.push_back(x);
    return xs;
}

// -------------------------------------------------------------------------- the written laws

TEST(MotionLawReference, TheWrittenOutLawsAreSelfConsistent) {
    // The references themselves: y(1/2) = 1/2 (this fixes A), y(1) = 1, and their derivatives
    // are those of y by central differences; the coefficients round to math.md §8's table.
    for (auto* law : {cycloid, harmonic, parabola, modifiedTrapezoid, modifiedSine, poly4567}) {
        EXPECT_NEAR(law(0.5).y, 0.5, 1e-15);
        EXPECT_NEAR(law(1.0).y, 1.0, 1e-15);
        EXPECT_NEAR(law(0.0).y, 0.0, 1e-15);
        constexpr double h = 1e-5;
        for (double x : samplesOfX()) {
            if (std::abs(x - 0.5) < 2 * h) continue;  // the parabola's a jumps at 1/2
            EXPECT_NEAR(law(x).v, (law(x + h).y - law(x - h).y) / (2 * h), 1e-8) << x;
            EXPECT_NEAR(law(x).a, (law(x + h).v - law(x - h).v) / (2 * h), 1e-7) << x;
            EXPECT_NEAR(law(x).j, (law(x + h).a - law(x - h).a) / (2 * h), 1e-5) << x;
        }
    }
    // math.md §8: modified trapezoid 2, 4.8881, 61.43; modified sine 1.7596, 5.5280, 69.47.
    EXPECT_NEAR(kTrapezoid.cv, 2.0, 1e-15);
    EXPECT_NEAR(kTrapezoid.ca, 4.8881, 0.5e-4);
    EXPECT_NEAR(kTrapezoid.cj, 61.43, 0.5e-2);
    EXPECT_NEAR(kSine.cv, 1.7596, 0.5e-4);
    EXPECT_NEAR(kSine.ca, 5.5280, 0.5e-4);
    EXPECT_NEAR(kSine.cj, 69.47, 0.5e-2);
    // Norton's Ca formula at the classic laws.
    EXPECT_NEAR(sccaCoefficients(0.25, 0.25).ca, kTrapezoidCa, 1e-14);
    EXPECT_NEAR(sccaCoefficients(0.25, 0.75).ca, kSineCa, 1e-14);
    EXPECT_NEAR(sccaCoefficients(0.5, 0.5).ca, kTwoPi, 1e-14);
    EXPECT_NEAR(sccaCoefficients(0.0, 1.0).ca, kPi * kPi / 2, 1e-14);
    EXPECT_NEAR(sccaCoefficients(0.0, 0.0).ca, 4.0, 1e-14);
}

// ----------------------------------------------------------------------------- inclined sine

TEST(MotionLawReference, InclinedSineWithoutEndVelocityIsTheCycloid) {
    DesignSegmentSpec rise = designSegment(MotionLawType::InclinedSine, 0, 0);
    const std::optional<MotionDesign> design = built(restToRest(rise, rise));
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    EXPECT_TRUE(m.jumps().empty());
    for (std::size_t k : {0u, 2u}) {
        const SegmentView s = viewOf(m, k);
        for (double x : samplesOfX()) {
            expectAt(s, x, cycloid(x), 1e-12,
                     "segment " + std::to_string(k) + " x " + std::to_string(x));
        }
        expectCoefficients(m.coefficients(k), {2.0, kTwoPi, 4 * kPi * kPi}, 1e-12, "vn 0");
    }
}

/// Inclined sine 0–90° (0 → 10 mm), a line 90–150° (to 16 mm: 0.1 mm/°), inclined sine 150–240°
/// (to 19 mm), a poly5 back to 0 at 360°; every joint at 0.1 mm/° and acceleration 0.
DesignSpec linesAndInclinedSines(double slopePerDeg = 0.1) {
    DesignSpec d;
    d.baseRadius = 40.0;
    DesignSegmentSpec first = designSegment(MotionLawType::InclinedSine, 90.0, 10.0);
    first.v0 = slopePerDeg;
    DesignSegmentSpec second = designSegment(MotionLawType::InclinedSine, 240.0, 19.0);
    second.v0 = slopePerDeg;
    DesignSegmentSpec back = designSegment(MotionLawType::Poly5, 360.0, 0.0);
    back.v0 = back.v1 = slopePerDeg;
    d.segments = {first, designSegment(MotionLawType::ConstantVelocity, 150.0, 16.0), second, back};
    return d;
}

TEST(MotionLawReference, InclinedSineIsItsClosedFormWithTheLinesSlope) {
    const std::optional<MotionDesign> design = built(linesAndInclinedSines());
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    // vn = v0·(stretch in degrees)/Δ: 0.1·90/10 = 0.9 and 0.1·90/3 = 3 (beyond 1: it dips).
    const std::pair<std::size_t, double> cases[] = {{0, 0.9}, {2, 3.0}};
    for (const auto& [k, vn] : cases) {
        const SegmentView s = viewOf(m, k);
        for (double x : samplesOfX()) {
            expectAt(s, x, inclinedSine(vn, x), 1e-12,
                     "vn " + std::to_string(vn) + " x " + std::to_string(x));
        }
        // y' runs from vn to 2 − vn (at x = 1/2); y'' = (1 − vn)·2π·sin 2πx; y''' its derivative.
        const LawCoefficients want{std::max(std::abs(vn), std::abs(2.0 - vn)),
                                   kTwoPi * std::abs(1.0 - vn),
                                   kTwoPi * kTwoPi * std::abs(1.0 - vn)};
        expectCoefficients(m.coefficients(k), want, 1e-12, "vn " + std::to_string(vn));
        expectCoefficients(sampled(s), want, 1e-9, "sampled, vn " + std::to_string(vn));
        // Its ends: velocity vn, acceleration 0.
        EXPECT_NEAR(s.at(0.0).v, vn, 1e-13);
        EXPECT_NEAR(s.at(0.0).a, 0.0, 1e-13);
        EXPECT_NEAR(s.at(1.0 - 1e-13).v, vn, 1e-11);
        EXPECT_NEAR(s.at(1.0 - 1e-13).a, 0.0, 1e-10);
    }
}

TEST(MotionLawReference, InclinedSineReturnsWithTheLinesSlope) {
    // The poly5 return of linesAndInclinedSines an inclined sine too (240–360°, 19 → 0 mm, at
    // 0.1 mm/° at both ends): vn = 0.1·120/(−19), negative; the cam is lines and inclined sines.
    DesignSpec d = linesAndInclinedSines();
    d.segments[3] = designSegment(MotionLawType::InclinedSine, 360.0, 0.0);
    d.segments[3].v0 = 0.1;
    const std::optional<MotionDesign> design = built(d);
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    EXPECT_TRUE(m.jumps().empty()) << m.jumps().front().text();
    const double vn = 0.1 * 120.0 / -19.0;
    const SegmentView s = viewOf(m, 3);
    for (double x : samplesOfX()) {
        expectAt(s, x, inclinedSine(vn, x), 1e-12, "x " + std::to_string(x));
    }
    const LawCoefficients want{2.0 - vn, kTwoPi * (1.0 - vn), kTwoPi * kTwoPi * (1.0 - vn)};
    expectCoefficients(m.coefficients(3), want, 1e-12, "return");
    expectCoefficients(sampled(s), want, 1e-9, "sampled return");
    // In mm/° at its ends, as the line's: +0.1.
    EXPECT_TRUE(relClose(m.liftAt(degToRad(240.0))[1] * kPi / 180.0, 0.1, 1e-12));
    EXPECT_TRUE(relClose(m.endOf(3)[1] * kPi / 180.0, 0.1, 1e-12));
}

TEST(MotionLawReference, LinesBetweenInclinedSinesJoinWithoutJumps) {
    const std::optional<MotionDesign> design = built(linesAndInclinedSines());
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    EXPECT_TRUE(m.jumps().empty()) << m.jumps().front().text();
    const double perDeg = kPi / 180.0;
    // The line's slope is 0.1 mm/° = 0.1·180/π mm/rad; at every joint the velocity on both
    // sides is 0.1 mm/° and the acceleration 0 (the left side just before the joint).
    for (double deg : {0.0, 90.0, 150.0, 240.0, 360.0}) {
        const double phi = degToRad(deg);
        const auto left = m.liftAt(phi - 1e-12), right = m.liftAt(phi);
        EXPECT_TRUE(relClose(left[1] * perDeg, 0.1, 1e-11)) << deg;
        EXPECT_TRUE(relClose(right[1] * perDeg, 0.1, 1e-12)) << deg;
        EXPECT_NEAR(left[2], 0.0, 1e-9) << deg;
        EXPECT_NEAR(right[2], 0.0, 1e-12) << deg;
        EXPECT_NEAR(left[0], right[0], 1e-11) << deg;
    }
    EXPECT_NEAR(m.liftAt(degToRad(120.0))[0], 13.0, 1e-12);
}

TEST(MotionLawReference, ARestToRestLawBesideALineIsRefused) {
    // The first inclined sine becomes a cycloid: it ends at rest, the line starts at 0.1 mm/°.
    DesignSpec d = linesAndInclinedSines();
    d.segments[0] = designSegment(MotionLawType::Cycloidal, 90.0, 10.0);
    d.segments[3].v1 = 0.0;  // so only the joint cycloid/line is wrong
    const auto m = MotionDesign::build(d);
    ASSERT_FALSE(m.ok());
    bool named = false;
    std::string all;
    for (const Diagnostic& e : m.errors()) {
        all += e.location + ": " + e.message + "\n";
        named = named || e.location.find("design.segments[0]") != std::string::npos ||
                e.location.find("design.segments[1]") != std::string::npos;
    }
    EXPECT_TRUE(named) << all;
    // The control: with the inclined sine (at 0.1 mm/° at both ends) in its place it builds.
    EXPECT_TRUE(MotionDesign::build(linesAndInclinedSines()).ok());
}

// ---------------------------------------------------- modified sine and trapezoid, inflection λ

TEST(MotionLawReference, ModifiedLawsTakeTheInflectionPoint) {
    struct Law {
        MotionLawType type;
        LawPoint (*symmetric)(double);
        LawCoefficients c;
    };
    const Law laws[] = {{MotionLawType::ModifiedTrapezoid, modifiedTrapezoid, kTrapezoid},
                        {MotionLawType::ModifiedSine, modifiedSine, kSine}};
    for (const Law& law : laws) {
        for (double lambda : {0.5, 0.3, 0.65, 0.2, 0.9}) {
            const std::string name =
                std::string(lawName(law.type)) + " λ " + std::to_string(lambda);
            DesignSegmentSpec seg = designSegment(law.type, 0, 0);
            seg.lambda = lambda;
            const std::optional<MotionDesign> design = built(restToRest(seg, seg));
            ASSERT_TRUE(design);
            const MotionDesign& m = *design;
            EXPECT_TRUE(m.jumps().empty()) << name;
            // Cv unchanged, Ca/(2 min(λ, 1 − λ)), Cj/(4 min(λ, 1 − λ)²).
            const double q = std::min(lambda, 1.0 - lambda);
            const LawCoefficients want{law.c.cv, law.c.ca / (2 * q), law.c.cj / (4 * q * q)};
            for (std::size_t k : {0u, 2u}) {  // the rise and the return
                const SegmentView s = viewOf(m, k);
                for (double x : samplesOfX()) {
                    expectAt(s, x, withInflection(law.symmetric, lambda, x), 1e-12,
                             name + " x " + std::to_string(x));
                }
                expectCoefficients(m.coefficients(k), want, 1e-12, name);
                expectCoefficients(sampled(s), want, 1e-9, "sampled " + name);
                // At λ: y = λ, y' = Cv, y'' = 0 from both sides; y, y', y'' continuous.
                const double phi = s.phi0 + lambda * s.h, d = 1e-9;
                const LawPoint left = s.at(lambda - d / s.h), right = s.at(lambda + d / s.h),
                               at = s.at(lambda);
                EXPECT_NEAR(at.y, lambda, 1e-13) << name;
                EXPECT_TRUE(relClose(at.v, law.c.cv, 1e-12)) << name;
                EXPECT_NEAR(at.a, 0.0, 1e-9) << name;
                EXPECT_NEAR(left.y, right.y, 2e-9 * law.c.cv) << name;  // 2d/h·y'
                EXPECT_NEAR(left.v, right.v, 1e-12) << name;            // y'' = 0 there
                EXPECT_NEAR(left.a, right.a, 4e-9 * want.cj) << name;
                EXPECT_NEAR(m.liftAt(phi)[0], s.s0 + lambda * s.delta, 1e-12) << name;
                // The ends at rest: y, y', y'' = 0 at 0 and 1, 1, 0, 0 at 1.
                expectAt(s, 0.0, {0.0, 0.0, 0.0, 0.0}, 1e-13, name + " start", false);
                expectAt(s, 1.0 - 1e-13, {1.0, 0.0, 0.0, 0.0}, 1e-9, name + " end", false);
            }
            if (lambda == 0.5) {  // math.md §8's values, to their last digit
                const LawCoefficients c = sampled(viewOf(m, 0));
                const LawCoefficients table = law.type == MotionLawType::ModifiedTrapezoid
                                                  ? LawCoefficients{2.0, 4.8881, 61.43}
                                                  : LawCoefficients{1.7596, 5.5280, 69.47};
                EXPECT_NEAR(c.cv, table.cv, 0.5e-4) << name;
                EXPECT_NEAR(c.ca, table.ca, 0.5e-4) << name;
                EXPECT_NEAR(c.cj, table.cj, 0.5e-2) << name;
            }
        }
    }
}

// ---------------------------------------------------------------------------------------- scca

TEST(MotionLawReference, SccaReproducesTheClassicLaws) {
    struct Case {
        double b, d;
        LawPoint (*law)(double);
        LawCoefficients c;
        const char* name;
    };
    const Case cases[] = {
        {0.25, 0.25, modifiedTrapezoid, kTrapezoid, "modified trapezoid"},
        {0.25, 0.75, modifiedSine, kSine, "modified sine"},
        {0.5, 0.5, cycloid, {2.0, kTwoPi, 4 * kPi * kPi}, "cycloid"},
        {0.0, 1.0, harmonic, {kPi / 2, kPi * kPi / 2, kPi * kPi * kPi / 2}, "harmonic"},
        // Constant acceleration: its jerk is 0 inside each half (a jumps at 0, 1/2 and 1).
        {0.0, 0.0, parabola, {2.0, 4.0, 0.0}, "constant acceleration"},
    };
    for (const Case& c : cases) {
        DesignSegmentSpec seg = designSegment(MotionLawType::Scca, 0, 0);
        seg.sccaB = c.b;
        seg.sccaD = c.d;
        const std::optional<MotionDesign> design = built(restToRest(seg, seg));
        ASSERT_TRUE(design);
        const MotionDesign& m = *design;
        for (std::size_t k : {0u, 2u}) {
            const SegmentView s = viewOf(m, k);
            for (double x : samplesOfX()) {
                expectAt(s, x, c.law(x), 1e-12, std::string(c.name) + " x " + std::to_string(x));
            }
            expectCoefficients(m.coefficients(k), c.c, 1e-12, c.name);
            expectCoefficients(sampled(s), c.c, 1e-9, std::string("sampled ") + c.name);
        }
    }
}

TEST(MotionLawReference, SccaIsNortonsAccelerationIntegrated) {
    struct Case {
        double b, d, ca, cv;
        const RefRow* rows;
        std::size_t n;
    };
    const Case cases[] = {
        {0.3, 0.5, kScca30x50Ca, kScca30x50Cv, kScca30x50, std::size(kScca30x50)},
        {0.1, 0.2, kScca10x20Ca, kScca10x20Cv, kScca10x20, std::size(kScca10x20)},
        {0.6, 0.15, kScca60x15Ca, kScca60x15Cv, kScca60x15, std::size(kScca60x15)},
        {0.0, 0.6, kScca0x60Ca, kScca0x60Cv, kScca0x60, std::size(kScca0x60)},
    };
    for (const Case& c : cases) {
        const std::string name = "b " + std::to_string(c.b) + " d " + std::to_string(c.d);
        // Norton's closed form against the quadrature (the script also checks it, to 1e-30).
        EXPECT_TRUE(relClose(sccaCoefficients(c.b, c.d).ca, c.ca, 1e-14)) << name;
        EXPECT_TRUE(relClose(sccaCoefficients(c.b, c.d).cv, c.cv, 1e-14)) << name;
        DesignSegmentSpec seg = designSegment(MotionLawType::Scca, 0, 0);
        seg.sccaB = c.b;
        seg.sccaD = c.d;
        const std::optional<MotionDesign> design = built(restToRest(seg, seg));
        ASSERT_TRUE(design);
        const MotionDesign& m = *design;
        const LawCoefficients want{c.cv, c.ca, sccaCoefficients(c.b, c.d).cj};
        for (std::size_t k : {0u, 2u}) {
            const SegmentView s = viewOf(m, k);
            for (std::size_t i = 0; i < c.n; ++i) {
                const RefRow& r = c.rows[i];
                expectAt(s, r.x, {r.y, r.v, r.a, r.j}, 1e-12, name + " x " + std::to_string(r.x));
            }
            expectCoefficients(m.coefficients(k), want, 1e-12, name);
            expectCoefficients(sampled(s), want, 1e-9, "sampled " + name);
        }
    }
}

// --------------------------------------------------------------------------------------- poly7

/// Two poly7 segments make the whole turn: 0–150° from 0 to 12 mm, 150–360° back, with the
/// boundary values of motion_law_reference.py (P7_A, P7_B) per degree, continuous at both joints.
constexpr std::array<double, 3> kP7A{0.05, 0.002, -0.0001}, kP7B{-0.03, -0.001, 0.00005};

DesignSpec twoPoly7() {
    DesignSegmentSpec rise = designSegment(MotionLawType::Poly7, 150.0, 12.0);
    DesignSegmentSpec back = designSegment(MotionLawType::Poly7, 360.0, 0.0);
    const auto ends = [](DesignSegmentSpec& s, const std::array<double, 3>& start,
                         const std::array<double, 3>& end) {
        std::tie(s.v0, s.a0, s.j0) = std::tuple(start[0], start[1], start[2]);
        std::tie(s.v1, s.a1, s.j1) = std::tuple(end[0], end[1], end[2]);
    };
    ends(rise, kP7A, kP7B);
    ends(back, kP7B, kP7A);
    DesignSpec d;
    d.baseRadius = 40.0;
    d.segments = {rise, back};
    return d;
}

/// How far a value of s, s', s'', s''' (per rad) of a poly7 may be off by rounding alone:
/// evaluating Σ c_n·u^n in double errs by at most γ_2n·Σ|c_n| (n = 7, γ_14 ≈ 14ε: Higham,
/// Accuracy and Stability of Numerical Algorithms, 2nd ed., §5.1), the k-th derivative by
/// γ_14·Σ n!/(n−k)!·|c_n|/h^k (the reference's kPoly7…Terms). Twice that (32ε) leaves room for
/// the rounding of the coefficients themselves.
double poly7Rounding(const double* terms, int k) {
    return 32 * std::numeric_limits<double>::epsilon() * terms[k];
}

TEST(MotionLawReference, Poly7MeetsItsEightBoundaryValues) {
    const std::optional<MotionDesign> design = built(twoPoly7());
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    EXPECT_TRUE(m.jumps().empty()) << m.jumps().front().text();
    // Segment 0 starts at 0° with A, ends at 150° with B; segment 1 starts with B, ends with A.
    // Each segment's own values at its ends (startOf, endOf; liftAt at a joint is the later
    // segment's), per degree as the spec gives them: s^(k) per rad times (π/180)^k.
    struct End {
        std::array<double, 4> s;
        double lift;
        std::array<double, 3> values;
        const double* terms;
        const char* what;
    };
    const End ends[] = {{m.startOf(0), 0.0, kP7A, kPoly7RiseTerms, "start of 0"},
                        {m.liftAt(0.0), 0.0, kP7A, kPoly7RiseTerms, "liftAt 0°"},
                        {m.endOf(0), 12.0, kP7B, kPoly7RiseTerms, "end of 0"},
                        {m.startOf(1), 12.0, kP7B, kPoly7ReturnTerms, "start of 1"},
                        {m.liftAt(degToRad(150.0)), 12.0, kP7B, kPoly7ReturnTerms, "liftAt 150°"},
                        {m.endOf(1), 0.0, kP7A, kPoly7ReturnTerms, "end of 1"}};
    for (const End& e : ends) {
        EXPECT_NEAR(e.s[0], e.lift, poly7Rounding(e.terms, 0)) << e.what;
        double perDegK = 1.0;
        for (int k = 1; k <= 3; ++k) {
            perDegK *= kPi / 180.0;
            EXPECT_NEAR(e.s[k] * perDegK, e.values[k - 1], poly7Rounding(e.terms, k) * perDegK)
                << e.what << " derivative " << k;
            // …which is within 1e-11 of each value (the brief's ~1e-12 where rounding allows).
            EXPECT_TRUE(relClose(e.s[k] * perDegK, e.values[k - 1], 1e-11))
                << e.what << " derivative " << k;
        }
    }
}

TEST(MotionLawReference, Poly7IsTheDegreeSevenPolynomialOfTheReference) {
    const std::optional<MotionDesign> design = built(twoPoly7());
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    struct Segment {
        const RefRow* rows;
        std::size_t n;
        const double* terms;
    };
    const Segment segments[] = {{kPoly7Rise, std::size(kPoly7Rise), kPoly7RiseTerms},
                                {kPoly7Return, std::size(kPoly7Return), kPoly7ReturnTerms}};
    for (std::size_t k = 0; k < 2; ++k) {
        const SegmentView view = viewOf(m, k);
        const double* terms = segments[k].terms;
        for (std::size_t i = 0; i < segments[k].n; ++i) {
            const RefRow& r = segments[k].rows[i];
            const auto s = m.liftAt(view.phi0 + r.x * view.h);
            const std::string at = "segment " + std::to_string(k) + " u " + std::to_string(r.x);
            EXPECT_NEAR(s[0], r.y, poly7Rounding(terms, 0)) << at;
            EXPECT_NEAR(s[1], r.v, poly7Rounding(terms, 1)) << at;
            EXPECT_NEAR(s[2], r.a, poly7Rounding(terms, 2)) << at;
            EXPECT_NEAR(s[3], r.j, poly7Rounding(terms, 3)) << at;
        }
        // Degree ≤ 7: the eighth difference of 9 equally spaced values vanishes, to the rounding
        // of the values (binomial weights summing to 256). A law of higher degree or a spline
        // leaves h⁸·y⁽⁸⁾, here of the order of 0.1 mm.
        for (double u0 : {0.0, 0.05, 0.11}) {
            const double step = 0.1;
            double diff = 0.0, binom = 1.0;
            for (int i = 0; i <= 8; ++i) {
                diff += ((8 - i) % 2 == 0 ? 1.0 : -1.0) * binom *
                        m.liftAt(view.phi0 + (u0 + i * step) * view.h)[0];
                binom = binom * (8 - i) / (i + 1);
            }
            EXPECT_NEAR(diff, 0.0, 256 * poly7Rounding(terms, 0)) << "segment " << k << " " << u0;
        }
        // Its coefficients are normalised like poly5's: the maxima of y', y'', y''' (sampled
        // here; kSampledCoefficients says why 1e-6).
        expectCoefficients(m.coefficients(k), sampled(view), kSampledCoefficients,
                           "poly7 " + std::to_string(k));
    }
}

TEST(MotionLawReference, Poly7AtRestIsPoly4567) {
    const std::optional<MotionDesign> design = built(restToRest(
        designSegment(MotionLawType::Poly7, 0, 0), designSegment(MotionLawType::Poly7, 0, 0)));
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    EXPECT_TRUE(m.jumps().empty());
    for (std::size_t k : {0u, 2u}) {
        const SegmentView s = viewOf(m, k);
        for (double x : samplesOfX()) {
            expectAt(s, x, poly4567(x), 1e-12, "x " + std::to_string(x));
        }
        // math.md §8: poly4567 2.1875, 7.5132, 52.5 (y'(1/2) and |y'''(1/2)| exactly).
        const LawCoefficients c = m.coefficients(k);
        EXPECT_TRUE(relClose(c.cv, 2.1875, 1e-12));
        EXPECT_NEAR(c.ca, 7.5132, 0.5e-4);
        EXPECT_TRUE(relClose(c.cj, 52.5, 1e-12));
        expectCoefficients(c, sampled(s), kSampledCoefficients, "poly7 at rest");
    }
}

// --------------------------------------------------------------------------------------- table

/// A 6-point table in the manner of Inventor's two-column (x, y) input, optionally with
/// velocities at x = 0.15 and 0.55 (motion_law_reference.py: TABLE_6, TABLE_6_V).
std::vector<MotionTablePoint> sixPoints(bool withVelocities) {
    std::vector<MotionTablePoint> t = {{0.0, 0.0, {}},  {0.15, 0.04, {}}, {0.4, 0.32, {}},
                                       {0.55, 0.6, {}}, {0.8, 0.95, {}},  {1.0, 1.0, {}}};
    if (withVelocities) {
        t[1].v = 0.5;
        t[3].v = 1.9;
    }
    return t;
}

std::optional<MotionDesign> tableDesign(const std::vector<MotionTablePoint>& points) {
    DesignSegmentSpec seg = designSegment(MotionLawType::Table, 0, 0);
    seg.table = points;
    return built(restToRest(seg, designSegment(MotionLawType::Cycloidal, 0, 0)));
}

/// The one-sided limits of y, y', y'' at x from the left (side −1) or right (+1): Taylor from
/// x ± δ with the derivatives there (the errors are δ⁴·y''''/24, δ³·y''''/6, δ²·y''''/2).
LawPoint limit(const SegmentView& s, double x, int side, double delta) {
    const LawPoint p = s.at(x + side * delta);
    const double e = -side * delta;
    return {p.y + e * p.v + e * e / 2 * p.a + e * e * e / 6 * p.j, p.v + e * p.a + e * e / 2 * p.j,
            p.a + e * p.j, p.j};
}

TEST(MotionLawReference, TableIsTheQuinticSplineOfTheReference) {
    const std::pair<bool, const RefRow*> cases[] = {{false, kTable6}, {true, kTable6V}};
    for (const auto& [withV, rows] : cases) {
        const std::vector<MotionTablePoint> points = sixPoints(withV);
        const std::string name = withV ? "with v" : "without v";
        const std::optional<MotionDesign> design = tableDesign(points);
        ASSERT_TRUE(design);
        const MotionDesign& m = *design;
        EXPECT_TRUE(m.jumps().empty()) << name;
        const SegmentView s = viewOf(m, 0);
        for (std::size_t i = 0; i < std::size(kTable6); ++i) {
            const RefRow& r = rows[i];
            expectAt(s, r.x, {r.y, r.v, r.a, r.j}, 1e-12, name + " x " + std::to_string(r.x));
        }
        // Through every point; the given velocities from both sides; at rest at both ends.
        for (std::size_t k = 0; k < points.size(); ++k) {
            const MotionTablePoint& p = points[k];
            const std::string at = name + " point " + std::to_string(k);
            if (k + 1 < points.size()) {
                EXPECT_NEAR(s.at(p.x).y, p.y, 1e-12) << at;
            }
            EXPECT_NEAR(limit(s, p.x, -1, 1e-7).y, p.y, 1e-12) << at;
            if (p.v) {
                EXPECT_NEAR(s.at(p.x).v, *p.v, 1e-12) << at;
                EXPECT_NEAR(limit(s, p.x, -1, 1e-7).v, *p.v, 1e-11) << at;
            }
        }
        expectAt(s, 0.0, {0.0, 0.0, 0.0, s.at(0.0).j}, 1e-13, name + " start", false);
        expectPoint(limit(s, 1.0, -1, 1e-7), {1.0, 0.0, 0.0, 0.0}, 1e-9, name + " end", false);
        // y, y', y'' continuous at every interior knot, y''' too (a knot with v is C3; one
        // without is C4). The one-sided limits from δ = 1e-7 (y, y', y'') and 1e-9 (y''': the
        // error δ·y'''' with |y''''| < 1e4 here).
        for (std::size_t k = 1; k + 1 < points.size(); ++k) {
            const double x = points[k].x;
            const std::string at = name + " knot " + std::to_string(x);
            const LawPoint l = limit(s, x, -1, 1e-7), r = limit(s, x, +1, 1e-7);
            EXPECT_NEAR(l.y, r.y, 1e-12) << at;
            EXPECT_NEAR(l.v, r.v, 1e-11) << at;
            EXPECT_NEAR(l.a, r.a, 1e-9) << at;
            EXPECT_NEAR(s.at(x - 1e-9).j, s.at(x + 1e-9).j, 1e-4) << at;
        }
    }
}

TEST(MotionLawReference, TableCoefficientsAreItsMaxima) {
    const std::optional<MotionDesign> design = tableDesign(sixPoints(true));
    ASSERT_TRUE(design);
    const SegmentView s = viewOf(*design, 0);
    expectCoefficients(design->coefficients(0), sampled(s), kSampledCoefficients, "table");
    // …and those of the reference's spline at its 40 points are no larger.
    for (const RefRow& r : kTable6V) {
        EXPECT_LE(std::abs(r.v), design->coefficients(0).cv * (1 + 1e-12));
        EXPECT_LE(std::abs(r.a), design->coefficients(0).ca * (1 + 1e-12));
        EXPECT_LE(std::abs(r.j), design->coefficients(0).cj * (1 + 1e-12));
    }
}

TEST(MotionLawReference, TableAtSpeedJoinsLines) {
    // linesAndInclinedSines with its second inclined sine (150–240°, 16 → 19 mm) a table that
    // starts and ends at the line's 0.1 mm/°: normalised y' = 0.1·90/3 = 3, and a = 0.
    DesignSpec d = linesAndInclinedSines();
    d.segments[2].law = MotionLawType::Table;
    d.segments[2].table = {{0.0, 0.0, 3.0}, {0.3, 0.5, {}}, {0.7, 0.8, {}}, {1.0, 1.0, 3.0}};
    const std::optional<MotionDesign> design = built(d);
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    EXPECT_TRUE(m.jumps().empty()) << m.jumps().front().text();
    const SegmentView s = viewOf(m, 2);
    for (const RefRow& r : kTableEndV) {
        expectAt(s, r.x, {r.y, r.v, r.a, r.j}, 1e-12, "x " + std::to_string(r.x));
    }
    expectAt(s, 0.0, {0.0, 3.0, 0.0, s.at(0.0).j}, 1e-12, "start", false);
    expectPoint(limit(s, 1.0, -1, 1e-7), {1.0, 3.0, 0.0, 0.0}, 1e-9, "end", false);
}

TEST(MotionLawReference, TableOfItsEndsIsPoly345) {
    // Two points: one quintic at rest with y'' = 0 at both ends, y = 10x³ − 15x⁴ + 6x⁵ (poly
    // 3-4-5; math.md §8: Cv 1.875, Ca 5.7735, Cj 60).
    const std::optional<MotionDesign> design = tableDesign({{0.0, 0.0, {}}, {1.0, 1.0, {}}});
    ASSERT_TRUE(design);
    const SegmentView s = viewOf(*design, 0);
    for (double x : samplesOfX()) {
        const double x2 = x * x;
        const LawPoint want{x2 * x * (10.0 - 15.0 * x + 6.0 * x2),
                            x2 * (30.0 - 60.0 * x + 30.0 * x2), x * (60.0 - 180.0 * x + 120.0 * x2),
                            60.0 - 360.0 * x + 360.0 * x2};
        expectAt(s, x, want, 1e-12, "x " + std::to_string(x));
    }
}

TEST(MotionLawReference, TableThroughPoly4567IsPoly4567) {
    // poly4567 is at rest with y'' = 0 at both ends as the spline is, so the spline through 21 of
    // its points is within the quintic spline's own interpolation error: the reference computes
    // that error (kPoly4567SplineDeviation, 4001 points at 40 digits); the implementation at the
    // same 4001 points may exceed it only by rounding.
    std::vector<MotionTablePoint> points;
    for (int k = 0; k <= 20; ++k) points.push_back({k / 20.0, poly4567(k / 20.0).y, {}});
    const std::optional<MotionDesign> design = tableDesign(points);
    ASSERT_TRUE(design);
    const MotionDesign& m = *design;
    const SegmentView s = viewOf(m, 0);
    std::array<double, 4> worst{};
    for (int i = 0; i < 4000; ++i) {  // x = 1 is the dwell's
        const double x = i / 4000.0;
        const LawPoint p = s.at(x), q = poly4567(x);
        worst = {std::max(worst[0], std::abs(p.y - q.y)), std::max(worst[1], std::abs(p.v - q.v)),
                 std::max(worst[2], std::abs(p.a - q.a)), std::max(worst[3], std::abs(p.j - q.j))};
    }
    const double rounding[] = {1e-13, 1e-12, 1e-10, 1e-8};
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_LE(worst[k], kPoly4567SplineDeviation[k] * (1 + 1e-6) + rounding[k]) << k;
    }
    EXPECT_LT(kPoly4567SplineDeviation[0], 1e-7);  // small: 6e-8 of the lift
}

}  // namespace
}  // namespace law_reference
}  // namespace cam
