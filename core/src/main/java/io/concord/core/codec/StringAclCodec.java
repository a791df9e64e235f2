package io.concord.core.codec;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.FipaStringWriter;
import io.concord.core.acl.Performative;
import io.concord.core.time.Clock;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The FIPA string representation of ACL (SC00070, {@code fipa.acl.rep.string.std}) as JADE 4.3
 * writes and reads it.
 *
 * <p><b>Writing</b> follows JADE's layout (upper-case performative, one slot group per line,
 * content always quoted with only {@code "} escaped, {@code :reply-by} in UTC, user parameters as
 * {@code :X-name}) but quotes every value that is not a plain ASCII word, so that JADE reads back
 * exactly what was meant. Content is not trimmed. Text content that ends in a backslash, which
 * JADE's escaping cannot express, is written as a byte string {@code #n"...}; byte content is
 * written as Base64 with {@code :X-JADE-Encoding Base64}, as JADE does.
 *
 * <p><b>Reading</b> is lenient where JADE is: any case and whitespace, quoted or bare values,
 * byte strings, nested expressions (kept as their text), {@code :reply-by} with or without
 * {@code Z} or relative ({@code +...}). It rejects, as JADE does, unknown parameters that are
 * neither FIPA nor {@code :X-}, and receivers or addresses not written as {@code (set ...)} or
 * {@code (sequence ...)}. Every error is an {@link AclParseException} naming the offset.
 */
public final class StringAclCodec implements AclCodec {
    /** The codec with the system clock (used only for relative {@code :reply-by}) and UTF-8. */
    public static final StringAclCodec INSTANCE = new StringAclCodec(Clock.system(), StandardCharsets.UTF_8);

    /** FIPA's name of this representation. */
    public static final String NAME = "fipa.acl.rep.string.std";

    static final int MAX_NESTING = 64;

    private final Clock clock;
    private final Charset charset;

    /**
     * @param clock   used only to resolve relative {@code :reply-by} times
     * @param charset of the byte form ({@code encode}/{@code decode}); JADE's default is US-ASCII
     */
    public StringAclCodec(Clock clock, Charset charset) {
        this.clock = clock;
        this.charset = charset;
    }

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public byte[] encode(AclMessage msg) {
        return encodeToString(msg).getBytes(charset);
    }

    @Override
    public AclMessage decode(byte[] data, int offset, int length) throws AclParseException {
        if (offset < 0 || length < 0 || offset + length > data.length) {
            throw new AclParseException(0, "a valid byte range", "offset " + offset + " length " + length);
        }
        return decode(new String(data, offset, length, charset));
    }

    /**
     * Writes a message in JADE's layout so that this codec reads back exactly the same message,
     * whatever it holds (Concord's own hops, logs). What JADE 4.3 cannot read in some field, such as
     * a protocol name that is not a word, is still written (quoted); {@link #encodeForJade} refuses
     * such a message instead.
     *
     * Never throws: {@code toString} and Concord's own hops use it.
     */
    public String encodeToString(AclMessage m) {
        return FipaStringWriter.write(m, false);
    }

    /**
     * Writes a message so that JADE 4.3's parser reads back every field as it is here.
     *
     * @throws IllegalArgumentException naming the field JADE cannot read, and why: a {@code :protocol}
     *         that is not a word, an address with spaces, parentheses, quotes or non-ASCII characters,
     *         more than one value ending in a backslash with non-ASCII text, a {@code :reply-by}
     *         outside the years 1 to 9999
     */
    public String encodeForJade(AclMessage m) {
        return FipaStringWriter.write(m, true);
    }

    /** Reads one message; the whole input must be that message (trailing whitespace allowed). */
    public AclMessage decode(String text) throws AclParseException {
        Reader r = new Reader(text, clock, NO_CHOICES);
        AclParseException first;
        try {
            return r.message();
        } catch (AclParseException e) {
            first = e;
        }
        // A string with an escaped-looking quote inside may have ended there (a value ending in a
        // backslash, as JADE writes it): try the shorter readings, the latest string first.
        int[] choices = r.nextChoices();
        for (int attempt = 0; choices != null && attempt < MAX_READINGS; attempt++) {
            r = new Reader(text, clock, choices);
            try {
                return r.message();
            } catch (AclParseException e) {
                choices = r.nextChoices();
            }
        }
        throw first;
    }

    private static final int[] NO_CHOICES = new int[0];
    /** At most this many other readings of ambiguous strings are tried after the first fails. */
    static final int MAX_READINGS = 32;

    /** A recursive-descent reader over the string, with a bounded nesting depth. */
    private static final class Reader {
        private final String s;
        private final Clock clock;
        private int pos;
        /** For each ambiguous string met so far, in order: how many ends it could have, and which was taken (0 = the last). */
        private final int[] forced;
        private int[] ends = new int[4];
        private int[] taken = new int[4];
        private int met;

        Reader(String s, Clock clock, int[] forced) {
            this.s = s;
            this.clock = clock;
            this.forced = forced;
        }

        /**
         * The choices for the next reading after this one failed: the latest ambiguous string that
         * can still end earlier does, the ones before keep theirs; null if none can.
         */
        int[] nextChoices() {
            for (int j = met - 1; j >= 0; j--) {
                if (taken[j] + 1 < ends[j]) {
                    int[] next = Arrays.copyOf(taken, j + 1);
                    next[j]++;
                    return next;
                }
            }
            return null;
        }

        AclMessage message() throws AclParseException {
            skipWs();
            expectChar('(', "'(' opening the message");
            int perfAt = pos;
            String perfName = word("a performative such as INFORM");
            Performative perf = Performative.fromWireName(perfName);
            if (perf == null) {
                throw new AclParseException(perfAt, "one of the 22 FIPA performatives", quote(perfName));
            }
            AclMessage m = new AclMessage(perf);
            boolean base64 = false;
            while (true) {
                skipWs();
                if (peek() == ')') {
                    pos++;
                    break;
                }
                int paramAt = pos;
                String param = word("a parameter such as :content, or ')'");
                if (param.length() < 2 || param.charAt(0) != ':') {
                    throw new AclParseException(paramAt, "a parameter name starting with ':'", quote(param));
                }
                String key = param.substring(1).toLowerCase(Locale.ROOT);
                switch (key) {
                    case "sender" -> m.setSender(aid(0));
                    case "receiver" -> {
                        m.clearAllReceiver();
                        m.getReceivers().addAll(aidCollection("receiver"));
                    }
                    case "reply-to" -> {
                        m.getReplyTo().clear();
                        m.getReplyTo().addAll(aidCollection("reply-to"));
                    }
                    case "content" -> content(m);
                    case "reply-with" -> m.setReplyWith(value());
                    case "in-reply-to" -> m.setInReplyTo(value());
                    case "encoding" -> m.setEncoding(value());
                    case "language" -> m.setLanguage(value());
                    case "ontology" -> m.setOntology(value());
                    case "protocol" -> m.setProtocol(value());
                    case "conversation-id" -> m.setConversationId(value());
                    case "reply-by" -> {
                        skipWs();
                        int at = pos;
                        String v = value();
                        m.setReplyByEpochMs(FipaDates.parse(v, at, clock));
                    }
                    default -> {
                        if (key.startsWith("x-") && key.length() > 2) {
                            String name = param.substring(3);
                            if (!AclMessage.isParameterName(name)) {
                                throw new AclParseException(paramAt,
                                        "a user-defined parameter name of letters, digits, '-', '_', '.'", quote(param));
                            }
                            String v = value();
                            if (name.equalsIgnoreCase("JADE-Encoding") && v.equalsIgnoreCase("Base64")) {
                                base64 = true;
                            } else {
                                m.addUserDefinedParameter(name, v);
                            }
                        } else {
                            throw new AclParseException(paramAt,
                                    "a FIPA message parameter or a user-defined :X-name", quote(param));
                        }
                    }
                }
            }
            skipWs();
            if (pos != s.length()) {
                throw new AclParseException(pos, "the end of the message", found());
            }
            if (base64 && m.getContent() != null && !m.hasByteSequenceContent()) {
                try {
                    m.setByteSequenceContent(Base64.getMimeDecoder().decode(m.getContent()));
                } catch (IllegalArgumentException e) {
                    throw new AclParseException(0, "Base64 content as :X-JADE-Encoding says",
                            "content that is not Base64 (" + e.getMessage() + ")");
                }
            }
            return m;
        }

        private void content(AclMessage m) throws AclParseException {
            skipWs();
            char c = peek();
            if (c == '#' && isByteStringAhead()) {
                m.setByteSequenceContent(byteString());
            } else {
                m.setContent(value());
            }
        }

        private List<AID> aidCollection(String slot) throws AclParseException {
            skipWs();
            expectChar('(', "'(set' holding the " + slot + " AIDs");
            int kwAt = pos;
            String kw = word("'set' or 'sequence'");
            if (!kw.equalsIgnoreCase("set") && !kw.equalsIgnoreCase("sequence")) {
                throw new AclParseException(kwAt, "'set' or 'sequence'", quote(kw));
            }
            List<AID> out = new ArrayList<>();
            while (true) {
                skipWs();
                if (peek() == ')') {
                    pos++;
                    return out;
                }
                out.add(aid(0));
            }
        }

        private AID aid(int depth) throws AclParseException {
            if (depth > 8) {
                throw new AclParseException(pos, "AIDs nested at most 8 deep in :resolvers", "deeper nesting");
            }
            skipWs();
            int start = pos;
            expectChar('(', "'(agent-identifier'");
            int kwAt = pos;
            String kw = word("'agent-identifier'");
            if (!kw.equalsIgnoreCase("agent-identifier")) {
                throw new AclParseException(kwAt, "'agent-identifier'", quote(kw));
            }
            String name = null;
            List<String> addresses = List.of();
            List<AID> resolvers = List.of();
            Map<String, String> user = new LinkedHashMap<>();
            while (true) {
                skipWs();
                if (peek() == ')') {
                    pos++;
                    break;
                }
                int slotAt = pos;
                String slot = word("an AID slot (:name, :addresses, :resolvers, :X-...) or ')'");
                String k = slot.toLowerCase(Locale.ROOT);
                switch (k) {
                    case ":name" -> name = value();
                    case ":addresses" -> addresses = sequenceOfWords();
                    case ":resolvers" -> {
                        skipWs();
                        expectChar('(', "'(sequence' of resolver AIDs");
                        int sAt = pos;
                        String sk = word("'sequence'");
                        if (!sk.equalsIgnoreCase("sequence") && !sk.equalsIgnoreCase("set")) {
                            throw new AclParseException(sAt, "'sequence'", quote(sk));
                        }
                        List<AID> rs = new ArrayList<>();
                        while (true) {
                            skipWs();
                            if (peek() == ')') {
                                pos++;
                                break;
                            }
                            rs.add(aid(depth + 1));
                        }
                        resolvers = rs;
                    }
                    default -> {
                        if (k.startsWith(":x-") && k.length() > 3) {
                            String slotName = slot.substring(3);
                            if (!AclMessage.isParameterName(slotName)) {
                                throw new AclParseException(slotAt, "an AID slot name of letters, digits, '-', '_', '.'",
                                        quote(slot));
                            }
                            user.put(slotName, value());
                        } else {
                            throw new AclParseException(slotAt, "an AID slot (:name, :addresses, :resolvers, :X-...)",
                                    quote(slot));
                        }
                    }
                }
            }
            if (name == null || name.isEmpty()) {
                throw new AclParseException(start, "an agent-identifier with a :name", "none");
            }
            return new AID(name, addresses, resolvers, user);
        }

        private List<String> sequenceOfWords() throws AclParseException {
            skipWs();
            expectChar('(', "'(sequence' of addresses");
            int kwAt = pos;
            String kw = word("'sequence'");
            if (!kw.equalsIgnoreCase("sequence") && !kw.equalsIgnoreCase("set")) {
                throw new AclParseException(kwAt, "'sequence'", quote(kw));
            }
            List<String> out = new ArrayList<>();
            while (true) {
                skipWs();
                if (peek() == ')') {
                    pos++;
                    return out;
                }
                out.add(value());
            }
        }

        /** A word, a quoted string, a byte string (as UTF-8 text) or a nested expression's text. */
        private String value() throws AclParseException {
            skipWs();
            char c = peek();
            if (c == '"') {
                return quoted();
            }
            if (c == '(') {
                return expression();
            }
            if (c == '#' && isByteStringAhead()) {
                return new String(byteString(), StandardCharsets.UTF_8);
            }
            return word("a value (a word, a \"string\" or an expression)");
        }

        /**
         * A quoted string as JADE's lexer reads it: {@code \"} stands for a quote, and the string
         * runs to the first quote without a backslash before it; if none follows, to the last
         * quote. A quote with a backslash before it may also have been the end (JADE escapes only
         * quotes, so a value ending in a backslash is written {@code "...\"}): such strings are
         * ambiguous, and a later reading may end them earlier.
         */
        private String quoted() throws AclParseException {
            int start = pos;
            int end = -1;
            int candidates = 0;
            int lastCandidate = -1;
            for (int p = start + 1; p < s.length(); p++) {
                if (s.charAt(p) == '"') {
                    if (s.charAt(p - 1) != '\\') {
                        end = p;
                        break;
                    }
                    candidates++;
                    lastCandidate = p;
                }
            }
            if (end < 0) {
                if (lastCandidate < 0) {
                    throw new AclParseException(start, "a closing '\"' for the string opened here", "the end of the input");
                }
                end = lastCandidate; // the longest string, as JADE reads it
                candidates--;
            }
            if (candidates > 0) {
                end = chooseEnd(start, end, candidates);
            }
            pos = end + 1;
            String body = s.substring(start + 1, end);
            return body.indexOf("\\\"") < 0 ? body : body.replace("\\\"", "\"");
        }

        /** Picks one of an ambiguous string's ends: the longest unless this reading says otherwise. */
        private int chooseEnd(int start, int longest, int shorter) {
            if (met == ends.length) {
                ends = Arrays.copyOf(ends, met * 2);
                taken = Arrays.copyOf(taken, met * 2);
            }
            int choice = met < forced.length ? forced[met] : 0;
            ends[met] = shorter + 1;
            taken[met] = choice;
            met++;
            if (choice == 0) {
                return longest;
            }
            // The choice-th escaped quote counted back from the longest end.
            int p = longest;
            for (int k = 0; k < choice; k++) {
                p = s.lastIndexOf("\\\"", p - 2) + 1;
            }
            return p;
        }

        private boolean isByteStringAhead() {
            int p = pos + 1;
            int digits = 0;
            while (p < s.length() && Character.isDigit(s.charAt(p)) && s.charAt(p) < 0x80) {
                p++;
                digits++;
            }
            return digits > 0 && p < s.length() && s.charAt(p) == '"';
        }

        /** {@code #n"} followed by exactly n bytes (counted in UTF-8). */
        private byte[] byteString() throws AclParseException {
            int start = pos;
            pos++;
            int digitsAt = pos;
            while (Character.isDigit(s.charAt(pos))) {
                pos++;
            }
            String digits = s.substring(digitsAt, pos);
            if (digits.length() > 9) {
                throw new AclParseException(digitsAt, "a byte-string length below 10^9", digits);
            }
            int n = Integer.parseInt(digits);
            pos++; // the quote
            int bytes = 0;
            int from = pos;
            while (bytes < n) {
                if (pos >= s.length()) {
                    throw new AclParseException(start, "a byte string of " + n + " bytes",
                            "only " + bytes + " bytes before the end of the input");
                }
                char c = s.charAt(pos);
                if (Character.isHighSurrogate(c) && pos + 1 < s.length() && Character.isLowSurrogate(s.charAt(pos + 1))) {
                    bytes += 4;
                    pos += 2;
                } else {
                    bytes += c < 0x80 ? 1 : c < 0x800 ? 2 : 3;
                    pos++;
                }
            }
            if (bytes != n) {
                throw new AclParseException(start, "a byte string of exactly " + n + " bytes",
                        "a character straddling its end");
            }
            return s.substring(from, pos).getBytes(StandardCharsets.UTF_8);
        }

        /** A balanced parenthesised expression, returned as its text; strings inside are skipped whole. */
        private String expression() throws AclParseException {
            int start = pos;
            int depth = 0;
            while (pos < s.length()) {
                char c = s.charAt(pos);
                if (c == '(') {
                    if (++depth > MAX_NESTING) {
                        throw new AclParseException(pos, "expressions nested at most " + MAX_NESTING + " deep",
                                "deeper nesting");
                    }
                    pos++;
                } else if (c == ')') {
                    pos++;
                    if (--depth == 0) {
                        return s.substring(start, pos);
                    }
                } else if (c == '"') {
                    quoted();
                } else if (c == '#' && isByteStringAhead()) {
                    byteString();
                } else {
                    pos++;
                }
            }
            throw new AclParseException(start, "a ')' closing the expression opened here", "the end of the input");
        }

        private String word(String expected) throws AclParseException {
            skipWs();
            int start = pos;
            while (pos < s.length()) {
                char c = s.charAt(pos);
                if (c <= ' ' || c == '(' || c == ')' || c == '"') {
                    break;
                }
                pos++;
            }
            if (pos == start) {
                throw new AclParseException(start, expected, found());
            }
            return s.substring(start, pos);
        }

        private void expectChar(char c, String expected) throws AclParseException {
            skipWs();
            if (peek() != c) {
                throw new AclParseException(pos, expected, found());
            }
            pos++;
        }

        private char peek() {
            return pos < s.length() ? s.charAt(pos) : '\0';
        }

        private void skipWs() {
            while (pos < s.length() && s.charAt(pos) <= ' ' && s.charAt(pos) != '\0') {
                pos++;
            }
        }

        private String found() {
            if (pos >= s.length()) {
                return "the end of the input";
            }
            int end = Math.min(s.length(), pos + 20);
            return quote(s.substring(pos, end) + (end < s.length() ? "..." : ""));
        }

        private static String quote(String v) {
            return "'" + v + "'";
        }
    }
}
