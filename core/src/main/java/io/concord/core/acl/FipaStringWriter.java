package io.concord.core.acl;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Base64;
import java.util.Calendar;
import java.util.GregorianCalendar;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TimeZone;

/**
 * Writes a message in the FIPA string representation (SC00070) in JADE 4.3's layout: the writing
 * half of {@code io.concord.core.codec.StringAclCodec}, here beside the message so that
 * {@link AclMessage#toString()} prints that form without the message model depending on the
 * codecs (which depend on it). The codec's javadoc has the rules.
 */
public final class FipaStringWriter {
    private static final DateTimeFormatter UTC =
            DateTimeFormatter.ofPattern("uuuuMMdd'T'HHmmssSSS'Z'").withZone(ZoneOffset.UTC);
    /** 1582-10-15T00:00Z, the first instant of the Gregorian calendar (from here on java.time agrees). */
    private static final long GREGORIAN_CUTOVER_MS = -12219292800000L;
    /** 10000-01-01T00:00Z: from here the year needs five digits. */
    private static final long YEAR_10000_MS = 253402300800000L;

    private FipaStringWriter() {
    }

    /**
     * The message in the string form: with {@code forJade}, refusing what JADE 4.3 could not read
     * back (see {@code StringAclCodec.encodeForJade}); without, never throwing.
     */
    public static String write(AclMessage m, boolean forJade) {
        return new Writer(forJade).message(m);
    }

    /**
     * Formats epoch milliseconds as {@code YYYYMMDDThhmmssSSSZ} in UTC.
     *
     * @throws IllegalArgumentException if the instant is outside the years 1 to 9999
     */
    /** Also for {@code FipaDates.format}. */
    public static String formatDate(long epochMs) {
        if (epochMs >= GREGORIAN_CUTOVER_MS) {
            if (epochMs >= YEAR_10000_MS) {
                throw new IllegalArgumentException("a FIPA date-time has a four-digit year; " + epochMs
                        + " ms is after the year 9999");
            }
            return UTC.format(Instant.ofEpochMilli(epochMs));
        }
        GregorianCalendar c = new GregorianCalendar(TimeZone.getTimeZone("UTC"));
        c.setTimeInMillis(epochMs);
        if (c.get(Calendar.ERA) == GregorianCalendar.BC) {
            throw new IllegalArgumentException("a FIPA date-time has a four-digit year from 1; " + epochMs
                    + " ms is before the year 1");
        }
        return String.format("%04d%02d%02dT%02d%02d%02d%03dZ", c.get(Calendar.YEAR), c.get(Calendar.MONTH) + 1,
                c.get(Calendar.DAY_OF_MONTH), c.get(Calendar.HOUR_OF_DAY), c.get(Calendar.MINUTE),
                c.get(Calendar.SECOND), c.get(Calendar.MILLISECOND));
    }

    /**
     * As {@link #formatDate}, but never refuses: an instant outside the years 1 to 9999 is written with
     * java.time's signed year of more or fewer digits (which FIPA's format cannot hold, so no reader
     * takes it back), for logs and for messages that never leave Concord.
     */
    /** Also for {@code FipaDates.formatAnyYear}. */
    public static String formatDateAnyYear(long epochMs) {
        try {
            return formatDate(epochMs);
        } catch (IllegalArgumentException outside) {
            return UTC.format(Instant.ofEpochMilli(epochMs));
        }
    }

    /**
     * One message's writer.
     *
     * <p>JADE escapes only the quote, so a quoted value that ends in a backslash looks as if its
     * closing quote were escaped. JADE's lexer takes the longest string it can, so it still reads
     * such a value right when no other quote follows it in the message: the writer puts one such
     * value (the content first) as the message's last slot. Any other one is written as a byte
     * string {@code #n"...}, which needs no escaping; JADE counts its length in characters where
     * FIPA counts bytes, so for JADE that only works for ASCII text.
     */
    private static final class Writer {
        private final boolean forJade;
        private final StringBuilder sb = new StringBuilder(256);
        private String lastSlot;
        private String lastValue;

        Writer(boolean forJade) {
            this.forJade = forJade;
        }

        String message(AclMessage m) {
            sb.append('(').append(m.getPerformative().wireName()).append('\n');
            if (m.getSender() != null) {
                sb.append(" :sender  ");
                writeAid(m.getSender());
                sb.append('\n');
            }
            if (!m.getReceivers().isEmpty()) {
                sb.append(" :receiver  ");
                writeAidSet(m.getReceivers());
                sb.append('\n');
            }
            if (!m.getReplyTo().isEmpty()) {
                sb.append(" :reply-to  ");
                writeAidSet(m.getReplyTo());
                sb.append('\n');
            }
            boolean base64 = false;
            if (forJade && m.hasByteSequenceContent() && m.getByteSequenceContent().length == 0) {
                // JADE reads :X-JADE-Encoding only with some content: for JADE, "no bytes" is empty text.
                sb.append(" :content  \"\"\n");
            } else if (m.hasByteSequenceContent()) {
                sb.append(" :content  ");
                writeQuoted(Base64.getEncoder().encodeToString(m.getByteSequenceContent()));
                sb.append('\n');
                base64 = true;
            } else if (m.getContent() != null) {
                String c = m.getContent();
                if (!goesLast("content", c)) {
                    sb.append(" :content  ");
                    writeQuoted(c);
                    sb.append('\n');
                }
            }
            slot("reply-with", m.getReplyWith());
            slot("in-reply-to", m.getInReplyTo());
            slot("encoding", m.getEncoding());
            slot("language", m.getLanguage());
            slot("ontology", m.getOntology());
            if (m.hasReplyBy()) {
                sb.append(" :reply-by  ").append(forJade ? formatDate(m.getReplyByEpochMs())
                        : formatDateAnyYear(m.getReplyByEpochMs()));
            }
            if (m.getProtocol() != null) {
                sb.append("\n :protocol  ");
                writeProtocol(m.getProtocol());
            }
            if (m.getConversationId() != null && !goesLast("conversation-id", m.getConversationId())) {
                sb.append("\n :conversation-id  ");
                writeValue("conversation-id", m.getConversationId());
            }
            if (base64) {
                sb.append(" :X-JADE-Encoding Base64");
            }
            for (Map.Entry<String, String> e : m.getUserDefinedParameters().entrySet()) {
                if (!goesLast("X-" + e.getKey(), e.getValue())) {
                    sb.append(" :X-").append(e.getKey()).append(' ');
                    writeValue("X-" + e.getKey(), e.getValue());
                }
            }
            if (lastSlot != null) {
                sb.append("\n :").append(lastSlot).append("  ");
                writeQuoted(lastValue);
            }
            sb.append(" )");
            return sb.toString();
        }

        private void slot(String name, String value) {
            if (value != null && !goesLast(name, value)) {
                sb.append(" :").append(name).append("  ");
                writeValue(name, value);
                sb.append(' ');
            }
        }

        /**
         * Keeps the slot for the end of the message if its value must be quoted (content always is)
         * and ends in a backslash, and the last place is still free (the content asks first).
         */
        private boolean goesLast(String slot, String v) {
            if (lastSlot != null || !v.endsWith("\\") || (!slot.equals("content") && isPlainWord(v))) {
                return false;
            }
            lastSlot = slot;
            lastValue = v;
            return true;
        }

        private void writeAidSet(List<AID> aids) {
            sb.append("(set ");
            for (AID a : aids) {
                writeAid(a);
                sb.append(' ');
            }
            sb.append(')');
        }

        private void writeAid(AID aid) {
            sb.append("( agent-identifier :name ");
            writeValue("the AID name", aid.name());
            sb.append(' ');
            if (!aid.addresses().isEmpty()) {
                sb.append(" :addresses (sequence ");
                for (String a : aid.addresses()) {
                    writeAddress(aid, a);
                    sb.append(' ');
                }
                sb.append(')');
            }
            if (!aid.resolvers().isEmpty()) {
                sb.append(" :resolvers (sequence ");
                for (AID r : aid.resolvers()) {
                    writeAid(r);
                    sb.append(' ');
                }
                sb.append(')');
            }
            for (Map.Entry<String, String> e : aid.userDefined().entrySet()) {
                sb.append(" :X-").append(e.getKey()).append(' ');
                writeValue("the AID slot X-" + e.getKey(), e.getValue());
            }
            sb.append(')');
        }

        /** JADE reads {@code :protocol} only as a bare word. */
        private void writeProtocol(String v) {
            if (isPlainWord(v)) {
                sb.append(v);
            } else if (forJade) {
                throw new IllegalArgumentException("the protocol '" + v + "' cannot be sent to JADE, whose parser reads "
                        + ":protocol only as a word (printable ASCII without spaces, quotes or parentheses, not "
                        + "starting with a digit, '-', '#' or ':'); name the protocol like fipa-request");
            } else {
                writeValue("protocol", v);
            }
        }

        /** JADE reads an address bare or quoted, but not one with spaces, parentheses or quotes. */
        private void writeAddress(AID aid, String a) {
            if (isPlainWord(a)) {
                sb.append(a);
                return;
            }
            if (forJade) {
                for (int i = 0; i < a.length(); i++) {
                    char c = a.charAt(i);
                    if (c <= 0x20 || c >= 0x7f || c == '"' || c == '(' || c == ')') {
                        throw new IllegalArgumentException("the address '" + a + "' of " + aid.name() + " cannot be sent "
                                + "to JADE, whose parser reads no spaces, quotes, parentheses or non-ASCII characters in "
                                + "an address; write it as a URL (percent-encoded)");
                    }
                }
                if (a.endsWith("\\")) {
                    throw new IllegalArgumentException("the address '" + a + "' of " + aid.name() + " cannot be sent "
                            + "to JADE: it is not a word and ends in a backslash");
                }
            }
            writeValue("an address", a);
        }

        /** Bare if a word, else quoted; a quoted value that ends in a backslash as a byte string. */
        private void writeValue(String slot, String v) {
            if (isPlainWord(v)) {
                sb.append(v);
            } else if (!v.endsWith("\\")) {
                writeQuoted(v);
            } else {
                writeByteString(slot, v);
            }
        }

        private void writeByteString(String slot, String v) {
            for (int i = 0; i < v.length(); i++) {
                if (v.charAt(i) >= 0x80) {
                    if (forJade) {
                        throw new IllegalArgumentException(slot + " '" + v + "' cannot be sent to JADE: it ends in a "
                                + "backslash, which JADE's quoting cannot express except as the message's last value "
                                + "(taken by " + lastSlot + "), and it is not ASCII, so it cannot be a byte string "
                                + "JADE counts the same way");
                    }
                    break;
                }
            }
            sb.append('#').append(v.getBytes(StandardCharsets.UTF_8).length).append('"').append(v);
        }

        private void writeQuoted(String v) {
            sb.append('"');
            for (int i = 0; i < v.length(); i++) {
                char c = v.charAt(i);
                if (c == '"') {
                    sb.append('\\');
                }
                sb.append(c);
            }
            sb.append('"');
        }
    }

    /**
     * A value JADE reads back unchanged when written bare: printable ASCII, no quote, parenthesis
     * or whitespace, and not starting like a number, a byte string or a parameter name.
     */
    static boolean isPlainWord(String v) {
        if (v.isEmpty() || "#0123456789-:".indexOf(v.charAt(0)) >= 0) {
            return false;
        }
        for (int i = 0; i < v.length(); i++) {
            char c = v.charAt(i);
            if (c <= 0x20 || c >= 0x7f || c == '"' || c == '(' || c == ')') {
                return false;
            }
        }
        return true;
    }
}
