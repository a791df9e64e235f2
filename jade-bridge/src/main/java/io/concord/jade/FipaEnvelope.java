package io.concord.jade;

import io.concord.core.acl.AID;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;

/**
 * The FIPA message envelope in XML (SC00085), as JADE 4.3 writes and reads it: {@code to},
 * {@code from}, {@code acl-representation}, {@code payload-length}, {@code payload-encoding},
 * {@code date} (local time, {@code yyyyMMdd'Z'HHmmssSSS}) and the mandatory
 * {@code intended-receiver}. Written without indentation, as JADE's reader needs.
 */
public record FipaEnvelope(List<AID> to, AID from, String aclRepresentation, int payloadLength, String payloadEncoding,
                           String date, List<AID> intendedReceivers) {
    public static final String STRING_REP = "fipa.acl.rep.string.std";
    private static final DateTimeFormatter DATE = DateTimeFormatter.ofPattern("yyyyMMdd'Z'HHmmssSSS");

    public FipaEnvelope {
        to = List.copyOf(to);
        intendedReceivers = List.copyOf(intendedReceivers);
    }

    /** An envelope for one receiver of a string-encoded payload. */
    public static FipaEnvelope forOne(AID receiver, AID sender, int payloadBytes) {
        return new FipaEnvelope(List.of(receiver), sender, STRING_REP, payloadBytes, "UTF-8",
                LocalDateTime.now().format(DATE), List.of(receiver));
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
     * Parses an envelope; the last {@code params} block wins for each field, as FIPA says.
     *
     * @throws IllegalArgumentException saying what is wrong
     */
    public static FipaEnvelope parse(String xml) {
        Document d;
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setXIncludeAware(false);
            f.setExpandEntityReferences(false);
            DocumentBuilder db = f.newDocumentBuilder();
            db.setErrorHandler(null);
            d = db.parse(new ByteArrayInputStream(xml.trim().getBytes(StandardCharsets.UTF_8)));
        } catch (Exception e) {
            throw new IllegalArgumentException("the envelope is not well-formed XML: " + e.getMessage());
        }
        Element root = d.getDocumentElement();
        if (!root.getTagName().equals("envelope")) {
            throw new IllegalArgumentException("the envelope's root element is <" + root.getTagName() + ">, not <envelope>");
        }
        List<AID> to = new ArrayList<>();
        List<AID> intended = new ArrayList<>();
        AID from = null;
        String rep = null;
        String enc = null;
        String date = null;
        int length = -1;
        NodeList params = root.getElementsByTagName("params");
        for (int i = 0; i < params.getLength(); i++) {
            for (Node n = params.item(i).getFirstChild(); n != null; n = n.getNextSibling()) {
                if (!(n instanceof Element e)) {
                    continue;
                }
                switch (e.getTagName()) {
                    case "to" -> to.addAll(aids(e));
                    case "intended-receiver" -> intended.addAll(aids(e));
                    case "from" -> from = aids(e).isEmpty() ? null : aids(e).get(0);
                    case "acl-representation" -> rep = e.getTextContent().trim();
                    case "payload-encoding" -> enc = e.getTextContent().trim();
                    case "date" -> date = e.getTextContent().trim();
                    case "payload-length" -> {
                        try {
                            length = Integer.parseInt(e.getTextContent().trim());
                        } catch (NumberFormatException x) {
                            throw new IllegalArgumentException("a bad payload-length '" + e.getTextContent() + "'");
                        }
                    }
                    default -> { }
                }
            }
        }
        if (to.isEmpty() && intended.isEmpty()) {
            throw new IllegalArgumentException("the envelope names no receiver (neither <to> nor <intended-receiver>)");
        }
        if (rep == null) {
            throw new IllegalArgumentException("the envelope has no <acl-representation>");
        }
        return new FipaEnvelope(to, from, rep, length, enc, date, intended);
    }

    private static List<AID> aids(Element parent) {
        List<AID> out = new ArrayList<>();
        NodeList ids = parent.getElementsByTagName("agent-identifier");
        for (int i = 0; i < ids.getLength(); i++) {
            Element id = (Element) ids.item(i);
            NodeList names = id.getElementsByTagName("name");
            if (names.getLength() == 0 || names.item(0).getTextContent().trim().isEmpty()) {
                throw new IllegalArgumentException("an agent-identifier without a name");
            }
            List<String> urls = new ArrayList<>();
            NodeList u = id.getElementsByTagName("url");
            for (int k = 0; k < u.getLength(); k++) {
                urls.add(u.item(k).getTextContent().trim());
            }
            out.add(new AID(names.item(0).getTextContent().trim(), urls.toArray(new String[0])));
        }
        return out;
    }

    /** Who to deliver to: the intended receivers, else the {@code to} list. */
    public List<AID> deliverTo() {
        return intendedReceivers.isEmpty() ? to : intendedReceivers;
    }
}
