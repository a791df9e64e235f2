package io.concord.jade;

import io.concord.core.acl.AID;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;

/**
 * The FIPA message envelope in XML (SC00085), as JADE 4.3 writes and reads it: {@code to},
 * {@code from}, {@code acl-representation}, {@code payload-length}, {@code payload-encoding},
 * {@code date} (local time, {@code yyyyMMdd'Z'HHmmssSSS}) and the mandatory
 * {@code intended-receiver}. Written without indentation, as JADE's reader needs.
 */
record FipaEnvelope(List<AID> to, AID from, String aclRepresentation, int payloadLength, String payloadEncoding,
                           String date, List<AID> intendedReceivers) {
    public static final String STRING_REP = "fipa.acl.rep.string.std";
    private static final DateTimeFormatter DATE = DateTimeFormatter.ofPattern("yyyyMMdd'Z'HHmmssSSS");

    public FipaEnvelope {
        to = List.copyOf(to);
        intendedReceivers = List.copyOf(intendedReceivers);
    }

    /**
     * An envelope for one receiver of a string-encoded payload, dated {@code epochMs} (the
     * caller's clock, {@link io.concord.core.time.Clock#epochMillis()}) in this host's time zone.
     */
    public static FipaEnvelope forOne(AID receiver, AID sender, int payloadBytes, long epochMs) {
        return new FipaEnvelope(List.of(receiver), sender, STRING_REP, payloadBytes, "UTF-8",
                LocalDateTime.ofInstant(Instant.ofEpochMilli(epochMs), ZoneId.systemDefault()).format(DATE), List.of(receiver));
    }

    public String toXml() {
        StringBuilder b = new StringBuilder(512);
        b.append("<?xml version=\"1.0\"?>\n<envelope><params index=\"1\">");
        for (AID a : to) {
            b.append("<to>");
            aid(b, a);
            b.append("</to>");
        }
        b.append("<from>");
        aid(b, from);
        b.append("</from><acl-representation>").append(esc(aclRepresentation)).append("</acl-representation>");
        b.append("<payload-length>").append(payloadLength).append("</payload-length>");
        if (payloadEncoding != null) {
            b.append("<payload-encoding>").append(esc(payloadEncoding)).append("</payload-encoding>");
        }
        b.append("<date>").append(esc(date)).append("</date>");
        for (AID a : intendedReceivers) {
            b.append("<intended-receiver>");
            aid(b, a);
            b.append("</intended-receiver>");
        }
        b.append("</params></envelope>");
        return b.toString();
    }

    private static void aid(StringBuilder b, AID a) {
        b.append("<agent-identifier><name>").append(esc(a.name())).append("</name>");
        if (!a.addresses().isEmpty()) {
            b.append("<addresses>");
            for (String u : a.addresses()) {
                b.append("<url>").append(esc(u)).append("</url>");
            }
            b.append("</addresses>");
        }
        b.append("</agent-identifier>");
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }

    /**
     * The streaming reader's factory, made once (finding and configuring one per envelope cost more
     * than reading the envelope). What arrives over HTTP is anyone's: no DTD, so no external or
     * expanding entities (a FIPA envelope has none).
     */
    private static final XMLInputFactory XML = xmlInputFactory();

    private static XMLInputFactory xmlInputFactory() {
        XMLInputFactory f = XMLInputFactory.newFactory();
        f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        f.setProperty(XMLInputFactory.IS_REPLACING_ENTITY_REFERENCES, false);
        f.setProperty(XMLInputFactory.IS_NAMESPACE_AWARE, false);
        return f;
    }

    /**
     * Parses an envelope in one pass over its text (StAX, no tree); the last {@code params} block
     * wins for each field, as FIPA says.
     *
     * @throws IllegalArgumentException saying what is wrong
     */
    public static FipaEnvelope parse(String xml) {
        try {
            return read(XML.createXMLStreamReader(new java.io.StringReader(xml.trim())));
        } catch (XMLStreamException | RuntimeException e) {
            if (e instanceof IllegalArgumentException bad && !(e instanceof NumberFormatException)) {
                throw bad;
            }
            throw new IllegalArgumentException("the envelope is not well-formed XML: " + e.getMessage());
        }
    }

    private static FipaEnvelope read(XMLStreamReader r) throws XMLStreamException {
        try {
            while (r.hasNext() && r.next() != XMLStreamConstants.START_ELEMENT) {
                if (r.getEventType() == XMLStreamConstants.DTD) {
                    throw new XMLStreamException("a DOCTYPE is not accepted in an envelope");
                }
            }
            if (r.getEventType() != XMLStreamConstants.START_ELEMENT) {
                throw new XMLStreamException("no element");
            }
            if (!r.getLocalName().equals("envelope")) {
                throw new IllegalArgumentException("the envelope's root element is <" + r.getLocalName() + ">, not <envelope>");
            }
            List<AID> to = new ArrayList<>();
            List<AID> intended = new ArrayList<>();
            AID from = null;
            String rep = null;
            String enc = null;
            String date = null;
            int length = -1;
            int depth = 1;
            while (depth > 0) {
                int e = r.next();
                if (e == XMLStreamConstants.END_ELEMENT) {
                    depth--;
                    continue;
                }
                if (e == XMLStreamConstants.DTD || e == XMLStreamConstants.ENTITY_REFERENCE) {
                    throw new XMLStreamException("an entity is not accepted in an envelope");
                }
                if (e != XMLStreamConstants.START_ELEMENT) {
                    continue;
                }
                if (depth != 2) { // <params> at depth 1 holds the fields; anything else is skipped whole
                    depth++;
                    if (depth > 2 || !r.getLocalName().equals("params")) {
                        skip(r);
                        depth--;
                    }
                    continue;
                }
                switch (r.getLocalName()) {
                    case "to" -> to.addAll(aids(r));
                    case "intended-receiver" -> intended.addAll(aids(r));
                    case "from" -> {
                        List<AID> f = aids(r);
                        from = f.isEmpty() ? null : f.get(0);
                    }
                    case "acl-representation" -> rep = text(r);
                    case "payload-encoding" -> enc = text(r);
                    case "date" -> date = text(r);
                    case "payload-length" -> {
                        String t = text(r);
                        try {
                            length = Integer.parseInt(t);
                        } catch (NumberFormatException x) {
                            throw new IllegalArgumentException("a bad payload-length '" + t + "'");
                        }
                    }
                    default -> skip(r);
                }
            }
            if (to.isEmpty() && intended.isEmpty()) {
                throw new IllegalArgumentException("the envelope names no receiver (neither <to> nor <intended-receiver>)");
            }
            if (rep == null) {
                throw new IllegalArgumentException("the envelope has no <acl-representation>");
            }
            return new FipaEnvelope(to, from, rep, length, enc, date, intended);
        } finally {
            r.close();
        }
    }

    /** The text of the element just started, trimmed; leaves the reader on its end. */
    private static String text(XMLStreamReader r) throws XMLStreamException {
        StringBuilder b = new StringBuilder();
        int depth = 1;
        while (depth > 0) {
            int e = r.next();
            switch (e) {
                case XMLStreamConstants.START_ELEMENT -> depth++;
                case XMLStreamConstants.END_ELEMENT -> depth--;
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE -> b.append(r.getText());
                case XMLStreamConstants.ENTITY_REFERENCE -> throw new XMLStreamException("an entity is not accepted in an envelope");
                default -> { }
            }
        }
        return b.toString().trim();
    }

    /** Skips the element just started, with all it holds. */
    private static void skip(XMLStreamReader r) throws XMLStreamException {
        text(r);
    }

    /** The agent-identifiers inside the element just started (at any depth); leaves the reader on its end. */
    private static List<AID> aids(XMLStreamReader r) throws XMLStreamException {
        List<AID> out = new ArrayList<>();
        int depth = 1;
        String name = null;
        List<String> urls = null;
        int idDepth = -1;
        while (depth > 0) {
            int e = r.next();
            if (e == XMLStreamConstants.START_ELEMENT) {
                depth++;
                String tag = r.getLocalName();
                if (tag.equals("agent-identifier") && idDepth < 0) {
                    idDepth = depth;
                    name = null;
                    urls = new ArrayList<>();
                } else if (idDepth > 0 && tag.equals("name") && name == null) {
                    name = text(r);
                    depth--;
                } else if (idDepth > 0 && tag.equals("url")) {
                    urls.add(text(r));
                    depth--;
                }
            } else if (e == XMLStreamConstants.END_ELEMENT) {
                if (depth == idDepth) {
                    if (name == null || name.isEmpty()) {
                        throw new IllegalArgumentException("an agent-identifier without a name");
                    }
                    out.add(new AID(name, urls.toArray(new String[0])));
                    idDepth = -1;
                }
                depth--;
            } else if (e == XMLStreamConstants.ENTITY_REFERENCE) {
                throw new XMLStreamException("an entity is not accepted in an envelope");
            }
        }
        return out;
    }

    /** Who to deliver to: the intended receivers, else the {@code to} list. */
    public List<AID> deliverTo() {
        return intendedReceivers.isEmpty() ? to : intendedReceivers;
    }
}
