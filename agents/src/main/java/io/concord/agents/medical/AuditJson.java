package io.concord.agents.medical;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.List;

/**
 * The audit trail as the Medical agent answers {@code QUERY-REF audit} (the latest transports,
 * newest first, as many as fit in {@link MedicalAgent#AUDIT_CHARS}) and {@code audit T3} (one,
 * with its story): {@code {"transports":[{"task":"T3","askedBy":...,"phases":{"awarded":...},...,"story":[...]}]}}
 * (docs/wheelchair-protocol.md).
 */
final class AuditJson {
    private static final ObjectMapper JSON = new ObjectMapper();

    private AuditJson() {
    }

    static String answer(TransportAudit audit, String query) {
        ObjectNode o = JSON.createObjectNode();
        ArrayNode a = o.putArray("transports");
        String task = query.length() > "audit".length() ? query.substring("audit".length()).trim() : "";
        if (!task.isEmpty()) {
            o.put("task", task);   // the answer to one transport's question, even when it is unknown
            TransportAudit.Entry e = audit.entry(task);
            if (e == null) {
                o.put("unknown", true);
            }
            if (e != null) {
                ObjectNode n = entry(a, e);
                ArrayNode story = n.putArray("story");
                int chars = n.toString().length();
                List<TransportAudit.Line> lines = e.story();
                int cut = 0;
                for (TransportAudit.Line l : lines) {
                    chars += l.text().length() + 40;
                    if (chars > MedicalAgent.AUDIT_CHARS) {
                        cut++;
                        continue;
                    }
                    story.addObject().put("atMs", l.atMs()).put("text", l.text());
                }
                if (cut > 0) {
                    n.put("storyCut", cut);
                }
            }
            return o.toString();
        }
        List<TransportAudit.Entry> all = audit.entries();
        int chars = 20;
        for (int i = all.size() - 1; i >= 0; i--) {
            ObjectNode n = entry(JSON.createArrayNode(), all.get(i));
            chars += n.toString().length() + 1;
            if (chars > MedicalAgent.AUDIT_CHARS) {
                o.put("older", i + 1);   // transports left out: ask for them one by one
                break;
            }
            a.add(n);
        }
        return o.toString();
    }

    private static ObjectNode entry(ArrayNode into, TransportAudit.Entry e) {
        ObjectNode n = into.addObject();
        n.put("task", e.task()).put("askedBy", e.askedBy()).put("conversation", e.conversation()).put("askedAtMs", e.askedAtMs())
                .put("from", e.from()).put("to", e.to()).put("priority", e.priority()).put("chair", e.chair()).put("auctions", e.auctions());
        ObjectNode p = n.putObject("phases");
        for (String ph : TransportAudit.PHASES) {
            Long at = e.phases().get(ph);
            if (at != null) {
                p.put(ph, at);
            }
        }
        n.put("endedAtMs", e.endedAtMs()).put("outcome", e.outcome()).put("reason", e.reason());
        return n;
    }
}
