/**
 * The works the lesson cards and the code's comments cite, one entry each. A card names its
 * references by key (lessonTexts.ts); the app's and the course page's bibliography list
 * them all.
 */
export interface Reference {
  authors: string;
  year: number;
  title: string;
  /** Journal, book or proceedings, with volume and pages where there are any. */
  where: string;
}

/** The first author's surname: the last word of the first name, "et al." aside (Hasselmann, not "al."). */
export const firstSurname = (reference: Reference): string =>
  reference.authors
    .split(',')[0]
    .replace(/\s+et al\.$/, '')
    .split(' ')
    .at(-1) ?? '';

export const BIBLIOGRAPHY = {
  airy1845: { authors: 'G. B. Airy', year: 1845, title: 'Tides and waves', where: 'Encyclopaedia Metropolitana, vol. 5, 241–396' },
  arthurMunkIsaacs1952: {
    authors: 'R. S. Arthur, W. H. Munk, J. D. Isaacs',
    year: 1952,
    title: 'The direct construction of wave rays',
    where: 'Transactions, American Geophysical Union 33(6), 855–865',
  },
  assarssonMoller2000: {
    authors: 'U. Assarsson, T. Möller',
    year: 2000,
    title: 'Optimized view frustum culling algorithms for bounding boxes',
    where: 'Journal of Graphics Tools 5(1), 9–22',
  },
  battjesJanssen1978: {
    authors: 'J. A. Battjes, J. P. F. M. Janssen',
    year: 1978,
    title: 'Energy loss and set-up due to breaking of random waves',
    where: 'Proceedings of the 16th International Conference on Coastal Engineering (ASCE), 569–587',
  },
  blinnNewell1976: {
    authors: 'J. F. Blinn, M. E. Newell',
    year: 1976,
    title: 'Texture and reflection in computer generated images',
    where: 'Communications of the ACM 19(10), 542–547',
  },
  bruneton2010: {
    authors: 'E. Bruneton, F. Neyret, N. Holzschuch',
    year: 2010,
    title: 'Real-time realistic ocean lighting using seamless transitions from geometry to BRDF',
    where: 'Computer Graphics Forum 29(2), 487–496 (Eurographics 2010)',
  },
  brunetonNeyret2008: {
    authors: 'E. Bruneton, F. Neyret',
    year: 2008,
    title: 'Precomputed atmospheric scattering',
    where: 'Computer Graphics Forum 27(4), 1079–1086 (EGSR 2008)',
  },
  callaghan2012: {
    authors: 'A. H. Callaghan, G. B. Deane, M. D. Stokes, B. Ward',
    year: 2012,
    title: 'Observed variation in the decay time of oceanic whitecap foam',
    where: 'Journal of Geophysical Research 117, C09015',
  },
  cooleyTukey1965: {
    authors: 'J. W. Cooley, J. W. Tukey',
    year: 1965,
    title: 'An algorithm for the machine calculation of complex Fourier series',
    where: 'Mathematics of Computation 19(90), 297–301',
  },
  coxMunk1954: {
    authors: 'C. Cox, W. Munk',
    year: 1954,
    title: 'Measurement of the roughness of the sea surface from photographs of the sun’s glitter',
    where: 'Journal of the Optical Society of America 44(11), 838–850',
  },
  darmon2014: {
    authors: 'A. Darmon, M. Benzaquen, E. Raphaël',
    year: 2014,
    title: 'Kelvin wake pattern at large Froude numbers',
    where: 'Journal of Fluid Mechanics 738, R3',
  },
  deanDalrymple1991: {
    authors: 'R. G. Dean, R. A. Dalrymple',
    year: 1991,
    title: 'Water Wave Mechanics for Engineers and Scientists',
    where: 'World Scientific, Advanced Series on Ocean Engineering 2',
  },
  dupuyBruneton2012: {
    authors: 'J. Dupuy, E. Bruneton',
    year: 2012,
    title: 'Real-time animation and rendering of ocean whitecaps',
    where: 'SIGGRAPH Asia 2012 Technical Briefs',
  },
  ebert2003: {
    authors: 'D. S. Ebert, F. K. Musgrave, D. Peachey, K. Perlin, S. Worley',
    year: 2003,
    title: 'Texturing and Modeling: A Procedural Approach, 3rd edition',
    where: 'Morgan Kaufmann, ch. 2 (lattice noises: value noise and gradient noise)',
  },
  fournierReeves1986: {
    authors: 'A. Fournier, W. T. Reeves',
    year: 1986,
    title: 'A simple model of ocean waves',
    where: 'SIGGRAPH ’86, Computer Graphics 20(4), 75–84',
  },
  gerstner1802: {
    authors: 'F. J. Gerstner',
    year: 1802,
    title: 'Theorie der Wellen',
    where: 'Abhandlungen der Königlichen Böhmischen Gesellschaft der Wissenschaften, Prague',
  },
  govindaraju2008: {
    authors: 'N. K. Govindaraju, B. Lloyd, Y. Dotsenko, B. Smith, J. Manferdelli',
    year: 2008,
    title: 'High performance discrete Fourier transforms on graphics processors',
    where: 'Proceedings of the 2008 ACM/IEEE Conference on Supercomputing (SC ’08)',
  },
  greene1986: {
    authors: 'N. Greene',
    year: 1986,
    title: 'Environment mapping and other applications of world projections',
    where: 'IEEE Computer Graphics and Applications 6(11), 21–29',
  },
  hasselmann1973: {
    authors: 'K. Hasselmann et al.',
    year: 1973,
    title: 'Measurements of wind-wave growth and swell decay during the Joint North Sea Wave Project (JONSWAP)',
    where: 'Ergänzungsheft zur Deutschen Hydrographischen Zeitschrift, Reihe A, 8(12)',
  },
  hasselmann1980: {
    authors: 'D. E. Hasselmann, M. Dunckel, J. A. Ewing',
    year: 1980,
    title: 'Directional wave spectra observed during JONSWAP 1973',
    where: 'Journal of Physical Oceanography 10, 1264–1280',
  },
  hecht2017: {
    authors: 'E. Hecht',
    year: 2017,
    title: 'Optics, 5th edition',
    where: 'Pearson, ch. 4 (Snell’s law, the Fresnel equations)',
  },
  henyeyGreenstein1941: {
    authors: 'L. G. Henyey, J. L. Greenstein',
    year: 1941,
    title: 'Diffuse radiation in the galaxy',
    where: 'Astrophysical Journal 93, 70–83',
  },
  holthuijsen2007: {
    authors: 'L. H. Holthuijsen',
    year: 2007,
    title: 'Waves in Oceanic and Coastal Waters',
    where: 'Cambridge University Press',
  },
  iec1999: {
    authors: 'International Electrotechnical Commission',
    year: 1999,
    title:
      'Multimedia systems and equipment – Colour measurement and management – Part 2-1: Colour management – Default RGB colour space – sRGB',
    where: 'IEC 61966-2-1',
  },
  kelvin1887: {
    authors: 'W. Thomson (Lord Kelvin)',
    year: 1887,
    title: 'On ship waves',
    where: 'Proceedings of the Institution of Mechanical Engineers 38, 409–434',
  },
  kinsman1965: {
    authors: 'B. Kinsman',
    year: 1965,
    title: 'Wind Waves: Their Generation and Propagation on the Ocean Surface',
    where: 'Prentice-Hall',
  },
  koschmieder1924: {
    authors: 'H. Koschmieder',
    year: 1924,
    title: 'Theorie der horizontalen Sichtweite',
    where: 'Beiträge zur Physik der freien Atmosphäre 12',
  },
  lamb1932: { authors: 'H. Lamb', year: 1932, title: 'Hydrodynamics, 6th edition', where: 'Cambridge University Press, §§ 228–255' },
  lighthill1978: {
    authors: 'J. Lighthill',
    year: 1978,
    title: 'Waves in Fluids',
    where: 'Cambridge University Press, § 3.10 (ship waves)',
  },
  losassoHoppe2004: {
    authors: 'F. Losasso, H. Hoppe',
    year: 2004,
    title: 'Geometry clipmaps: terrain rendering using nested regular grids',
    where: 'ACM Transactions on Graphics 23(3), 769–776 (SIGGRAPH 2004)',
  },
  mcCowan1894: {
    authors: 'J. McCowan',
    year: 1894,
    title: 'On the highest wave of permanent type',
    where: 'Philosophical Magazine, series 5, 38(233), 351–358',
  },
  mitsuyasu1975: {
    authors: 'H. Mitsuyasu et al.',
    year: 1975,
    title: 'Observations of the directional spectrum of ocean waves using a cloverleaf buoy',
    where: 'Journal of Physical Oceanography 5, 750–760',
  },
  monahan1980: {
    authors: 'E. C. Monahan, I. O’Muircheartaigh',
    year: 1980,
    title: 'Optimal power-law description of oceanic whitecap coverage dependence on wind speed',
    where: 'Journal of Physical Oceanography 10, 2094–2099',
  },
  morel1974: {
    authors: 'A. Morel',
    year: 1974,
    title: 'Optical properties of pure water and pure sea water',
    where: 'Optical Aspects of Oceanography, eds. N. G. Jerlov, E. Steemann Nielsen, Academic Press, 1–24',
  },
  morel1988: {
    authors: 'A. Morel',
    year: 1988,
    title: 'Optical modeling of the upper ocean in relation to its biogenous matter content (case I waters)',
    where: 'Journal of Geophysical Research 93(C9), 10749–10768',
  },
  morelPrieur1977: {
    authors: 'A. Morel, L. Prieur',
    year: 1977,
    title: 'Analysis of variations in ocean color',
    where: 'Limnology and Oceanography 22(4), 709–722',
  },
  perlin1985: { authors: 'K. Perlin', year: 1985, title: 'An image synthesizer', where: 'SIGGRAPH ’85, Computer Graphics 19(3), 287–296' },
  phillips1958: {
    authors: 'O. M. Phillips',
    year: 1958,
    title: 'The equilibrium range in the spectrum of wind-generated waves',
    where: 'Journal of Fluid Mechanics 4(4), 426–434',
  },
  piersonMoskowitz1964: {
    authors: 'W. J. Pierson, L. Moskowitz',
    year: 1964,
    title: 'A proposed spectral form for fully developed wind seas based on the similarity theory of S. A. Kitaigorodskii',
    where: 'Journal of Geophysical Research 69(24), 5181–5190',
  },
  popeFry1997: {
    authors: 'R. M. Pope, E. S. Fry',
    year: 1997,
    title: 'Absorption spectrum (380–700 nm) of pure water. II. Integrating cavity measurements',
    where: 'Applied Optics 36(33), 8710–8723',
  },
  rabaudMoisy2013: {
    authors: 'M. Rabaud, F. Moisy',
    year: 2013,
    title: 'Ship wakes: Kelvin or Mach angle?',
    where: 'Physical Review Letters 110, 214503',
  },
  reinhard2002: {
    authors: 'E. Reinhard, M. Stark, P. Shirley, J. Ferwerda',
    year: 2002,
    title: 'Photographic tone reproduction for digital images',
    where: 'ACM Transactions on Graphics 21(3), 267–276 (SIGGRAPH 2002)',
  },
  schlick1994: {
    authors: 'C. Schlick',
    year: 1994,
    title: 'An inexpensive BRDF model for physically-based rendering',
    where: 'Computer Graphics Forum 13(3), 233–246',
  },
  stewart2008: {
    authors: 'R. H. Stewart',
    year: 2008,
    title: 'Introduction to Physical Oceanography',
    where: 'Texas A&M University, ch. 16',
  },
  strugar2009: {
    authors: 'F. Strugar',
    year: 2009,
    title: 'Continuous distance-dependent level of detail for rendering heightmaps',
    where: 'Journal of Graphics, GPU, and Game Tools 14(4), 57–74',
  },
  tessendorf2001: {
    authors: 'J. Tessendorf',
    year: 2001,
    title: 'Simulating ocean water',
    where: 'SIGGRAPH 2001 course notes, Simulating Nature: Realistic and Interactive Techniques',
  },
  tessendorf2004: {
    authors: 'J. Tessendorf',
    year: 2004,
    title: 'Interactive water surfaces',
    where: 'Game Programming Gems 4, ed. A. Kirmse, Charles River Media, 265–274',
  },
  thorntonGuza1983: {
    authors: 'E. B. Thornton, R. T. Guza',
    year: 1983,
    title: 'Transformation of wave height distribution',
    where: 'Journal of Geophysical Research 88(C10), 5925–5938',
  },
  walter2007: {
    authors: 'B. Walter, S. R. Marschner, H. Li, K. E. Torrance',
    year: 2007,
    title: 'Microfacet models for refraction through rough surfaces',
    where: 'Eurographics Symposium on Rendering 2007, 195–206',
  },
  watt1990: {
    authors: 'M. Watt',
    year: 1990,
    title: 'Light-water interaction using backward beam tracing',
    where: 'SIGGRAPH ’90, Computer Graphics 24(4), 377–385',
  },
  welch1967: {
    authors: 'P. D. Welch',
    year: 1967,
    title:
      'The use of fast Fourier transform for the estimation of power spectra: a method based on time averaging over short, modified periodograms',
    where: 'IEEE Transactions on Audio and Electroacoustics 15(2), 70–73',
  },
  zhao2005: {
    authors: 'H. Zhao',
    year: 2005,
    title: 'A fast sweeping method for Eikonal equations',
    where: 'Mathematics of Computation 74(250), 603–627',
  },
} satisfies Record<string, Reference>;

export type ReferenceKey = keyof typeof BIBLIOGRAPHY;

/** `keys` in a reference list's order: by first author's surname, then year (the app's drawer and the course page). */
export function bySurnameAndYear(keys: readonly ReferenceKey[]): ReferenceKey[] {
  return [...keys].sort((a, b) => {
    const [p, q] = [BIBLIOGRAPHY[a], BIBLIOGRAPHY[b]];
    return firstSurname(p).localeCompare(firstSurname(q), 'en') || p.year - q.year;
  });
}
