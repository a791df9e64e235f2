package io.concord.core.content;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * The FIPA-SL content language (SC00008), reader and writer, in the form JADE 4.3's
 * {@code SLCodec} writes and reads: a content expression is a list of elements in parentheses,
 * {@code ((action (agent-identifier :name a@P) (Sell :book (Book :title "X"))))}.
 *
 * <p>What is written, and how (each byte as JADE's writer gives it):
 * <ul>
 * <li>a string is bare when it is an SL word, otherwise quoted with only {@code "} escaped (as
 * {@code \"}); a backslash is written as it is and read back as it is, so a string with a
 * backslash at its end or just before a quote cannot be written (JADE writes such a string, but
 * cannot read it back: here the writer refuses it);</li>
 * <li>integers in decimal, floating point numbers as Java prints them, booleans as
 * {@code true}/{@code false};</li>
 * <li>dates as {@code yyyyMMddTHHmmssSSSZ} in UTC (a date read without {@code Z} is taken as
 * UTC too);</li>
 * <li>byte strings as {@code #N"} followed by N characters of Base64;</li>
 * <li>{@code true} and {@code false} as bare atomic formulas ({@code (and true (not false))}, a
 * content of just {@code (true)});</li>
 * <li>a content of one element as {@code (e)}, of several as {@code (e1 e2 )} (a space after
 * each).</li>
 * </ul>
 * Dates are carried to the millisecond; finer parts of an {@link java.time.Instant} are dropped.
 *
 * <p>The profile ({@link Profile#SL0}, {@link Profile#SL1}, {@link Profile#SL2}) decides which
 * operators are accepted; the arity of each operator is checked. Limits: nesting depth
 * ({@value #DEFAULT_MAX_DEPTH} by default) and text length ({@value #DEFAULT_MAX_CHARS}
 * characters by default). The reader works in one pass, so its time and memory are linear in the
 * length of the text, and its recursion is bounded by the depth limit.
 *
 * <p>Instances are immutable and thread-safe.
 */
public final class SlCodec {

    /** The default limit of nesting of parentheses. */
    public static final int DEFAULT_MAX_DEPTH = 64;
    /** The default limit of a text's length, in characters (1 MiB). */
    public static final int DEFAULT_MAX_CHARS = 1 << 20;

    /** The SL subsets of FIPA SC00008. */
    public enum Profile {
        /** Atomic formulas, actions, {@code done}, {@code result}, {@code =}, referential expressions. */
        SL0("fipa-sl0"),
        /** SL0 plus {@code not}, {@code and}, {@code or}. */
        SL1("fipa-sl1"),
        /** SL1 plus {@code implies}, {@code equiv}, {@code forall}, {@code exists} and the modal {@code B}, {@code U}, {@code PG}, {@code I}. */
        SL2("fipa-sl2"),
        /** Full SL: everything SL2 accepts (the name JADE's SLCodec registers by default). */
        SL("fipa-sl");

        private final String languageName;

        Profile(String languageName) {
            this.languageName = languageName;
        }

        /** The value of the message's {@code :language} slot. */
        public String languageName() {
            return languageName;
        }
    }

    /** Each operator's arity, and the least profile that has it. */
    static final Map<String, Integer> ARITY = Map.ofEntries(
            Map.entry("action", 2), Map.entry("done", 1), Map.entry("result", 2), Map.entry("=", 2),
            Map.entry("iota", 2), Map.entry("any", 2), Map.entry("all", 2),
            Map.entry("not", 1), Map.entry("and", 2), Map.entry("or", 2),
            Map.entry("implies", 2), Map.entry("equiv", 2), Map.entry("forall", 2), Map.entry("exists", 2),
            Map.entry("B", 2), Map.entry("U", 2), Map.entry("PG", 2), Map.entry("I", 2));
    static final Set<String> SL1_OPERATORS = Set.of("not", "and", "or");
    static final Set<String> SL2_OPERATORS = Set.of("implies", "equiv", "forall", "exists", "B", "U", "PG", "I");

    private final Profile profile;
    private final int maxDepth;
    private final int maxChars;

    /** Full SL with the default limits. */
    public SlCodec() {
        this(Profile.SL, DEFAULT_MAX_DEPTH, DEFAULT_MAX_CHARS);
    }

    /**
     * A codec for one profile and limits.
     *
     * @param profile  which operators are accepted
     * @param maxDepth the deepest nesting of parentheses read or written, at least 2
     * @param maxChars the longest text read, at least 2
     */
    public SlCodec(Profile profile, int maxDepth, int maxChars) {
        this.profile = Objects.requireNonNull(profile, "profile");
        if (maxDepth < 2 || maxChars < 2) {
            throw new IllegalArgumentException("maxDepth and maxChars must be at least 2");
        }
        this.maxDepth = maxDepth;
        this.maxChars = maxChars;
    }

    /** The profile. */
    public Profile profile() {
        return profile;
    }

    /** The language name for the {@code :language} slot, such as {@code fipa-sl}. */
    public String languageName() {
        return profile.languageName();
    }

    /**
     * Reads a content expression: a list of elements in parentheses.
     *
     * @throws SlParseException for malformed text, an operator outside the profile, or a limit passed
     */
    public List<AbsObject> read(String text) throws SlParseException {
        Objects.requireNonNull(text, "text");
        if (text.length() > maxChars) {
            throw new SlParseException("text of " + text.length() + " characters is over the limit of " + maxChars, maxChars);
        }
        return new SlReader(text, this).content();
    }

    /**
     * Writes a content expression.
     *
     * @throws ContentException for a value SL cannot carry, an operator outside the profile, or
     *                          content nested deeper than the limit
     */
    public String write(List<? extends AbsObject> elements) throws ContentException {
        return SlWriter.write(elements, this);
    }

    /** Writes one element as a content expression. */
    public String write(AbsObject element) throws ContentException {
        return write(List.of(element));
    }

    int maxDepth() {
        return maxDepth;
    }

    /** Null if the compound is fine in this profile, else why not. */
    String checkOperator(AbsCompound c) {
        Integer arity = ARITY.get(c.name());
        if (arity == null) {
            return null;
        }
        boolean sl1 = SL1_OPERATORS.contains(c.name());
        boolean sl2 = SL2_OPERATORS.contains(c.name());
        if ((sl1 && profile == Profile.SL0) || (sl2 && (profile == Profile.SL0 || profile == Profile.SL1))) {
            return "operator " + c.name() + " is not in " + profile;
        }
        if (c.slots().size() != arity) {
            return "operator " + c.name() + " takes " + arity + " argument(s), got " + c.slots().size();
        }
        boolean logical = sl1 || sl2 || c.name().equals("done");
        if (logical && c.isNamed()) {
            return "operator " + c.name() + " takes positional arguments";
        }
        if ((c.name().equals("forall") || c.name().equals("exists"))
                && !(c.slots().get(0).value() instanceof AbsVariable)) {
            return "operator " + c.name() + " must bind a variable";
        }
        return null;
    }
}
